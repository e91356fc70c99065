package org.emini.harness.fuzz;

/** Judges one input in the worker process: the loader under fuzz, then a few ticks of what it built. */
interface Checker {
    /** The verdict; a failure of the checker itself is the sandbox's to catch and report as a crash. */
    Verdict check(byte[] input);
}
