"""emini-oracle: runs Emini scenario files in pymunk 7.3.1 (Chipmunk2D) and writes harness traces.

The mapping of every scenario element to pymunk is documented in oracle-py/MAPPING.md.
"""

__version__ = "0.1.0"
