package org.emini.harness.metrics;

/**
 * How deep two bodies (or a body and the landscape) overlapped over a run, at its samples.
 *
 * @param a the first body's scene name (the one the scene creates first)
 * @param b the second body's, or {@code landscape}
 * @param max the deepest overlap at a sample (px)
 * @param mean the mean depth of the pair's overlapping contact points over the samples (px)
 * @param samples how many samples found the pair overlapping
 */
public record PenetrationPair(String a, String b, double max, double mean, int samples) {
}
