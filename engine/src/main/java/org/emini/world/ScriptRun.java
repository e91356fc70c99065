package org.emini.world;

import org.emini.dynamics.Body;
import org.emini.event.Script;

/** One script running on one body: where it is in the script (the original's body-script pair). */
final class ScriptRun {
    final Script script;
    final Body body;
    private int element;
    private int ticks;
    private boolean restarted;

    ScriptRun(Script script, Body body) {
        this.script = script;
        this.body = body;
    }

    ScriptRun(ScriptRun other, Body body) {
        this(other.script, body);
        element = other.element;
        ticks = other.ticks;
        restarted = other.restarted;
    }

    /**
     * Runs one tick of the script; false once the run has ended. Timing as the original's: the
     * first element lasts its ticks, later ones (and the first after a restart) one more; after the
     * last element one idle tick, then a restart or the end.
     */
    boolean step(float dt) {
        int n = script.getElementCount();
        if (element == n) {
            element++;
            return true;
        }
        if (element > n) {
            if (!script.isRestarting() || n == 0) {
                return false;
            }
            element = 0;
            ticks = 0;
            restarted = true;
        }
        apply(element, dt);
        ticks++;
        int length = script.getTicks(element);
        if (length != 0 && ticks >= (element == 0 && !restarted ? length : length + 1)) {
            element++;
            ticks = 0;
        }
        return true;
    }

    private void apply(int i, float dt) {
        float a = script.getA(i);
        float b = script.getB(i);
        switch (script.getType(i)) {
            case Script.POSITION:
                body.setPosition(a, b);
                break;
            case Script.VELOCITY:
                if (!body.isStatic()) {
                    body.setVelocity(a, b);
                }
                break;
            case Script.ACCELERATION:
                body.applyAcceleration(a, b, dt);
                break;
            case Script.ANGLE:
                body.setAngle(a);
                break;
            case Script.ANGULAR_VELOCITY:
                if (!body.isStatic()) {
                    body.setAngularVelocity(a);
                }
                break;
            case Script.ANGULAR_ACCELERATION:
                if (body.isDynamic() && body.canRotate()) {
                    body.setAngularVelocity(body.getAngularVelocity() + a * dt);
                }
                break;
            default:
                break;
        }
    }
}
