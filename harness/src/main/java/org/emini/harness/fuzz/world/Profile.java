package org.emini.harness.fuzz.world;

/** What kind of world the generator makes; each invariant and relation says which it applies to. */
public enum Profile {
    /** Every feature at random (values in the ranges a game uses). */
    GENERAL,
    /**
     * No energy sources: no motors, forces, springs, elasticity or removals, joints made where both
     * bodies are; the energy bound applies.
     */
    PASSIVE,
    /** Extreme values (huge speeds, forces, mass ratios, tiny and huge bodies): only a clear error may stop a tick. */
    EXTREME,
    /** One dynamic body per lane over a floor, or hanging from a pivot: no body meets another dynamic body. */
    SEPARATED,
    /** No contacts at all: projectiles, pendulums, springs, motors and forces (smooth motion). */
    SMOOTH,
    /** Only what a scene file can say (no events, forces, bullets, motor modes, ...): for the format round trip. */
    SCENE
}
