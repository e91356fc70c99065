/**
 * What the engine's packages share and users do not need: argument checks, the heapsort, the lists
 * that queue changes made during a tick, id pools, the worker threads. Not part of the API: public
 * only so that the engine's packages can use it, and it may change in any release.
 */
package org.emini.internal;
