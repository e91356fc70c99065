/**
 * Collision detection: broadphase, narrowphase and contact manifolds.
 */
package org.emini.collision;
