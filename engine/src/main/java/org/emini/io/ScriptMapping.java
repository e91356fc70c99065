package org.emini.io;

import java.util.List;
import org.emini.dynamics.Body;
import org.emini.event.Script;
import org.emini.world.World;

/** Builds a world file's scripts and starts them on the bodies of its script-body table. */
final class ScriptMapping {
    private ScriptMapping() {
    }

    static void build(PhyWorld document, World world, BuildResult r) {
        List<PhyScript> stored = document.getScripts();
        Script[] scripts = new Script[stored.size()];
        for (int i = 0; i < scripts.length; i++) {
            scripts[i] = script(stored.get(i), i, r);
            world.addScript(scripts[i]);
        }
        List<PhyScriptBinding> rows = document.getScriptBindings();
        for (int i = 0; i < rows.size(); i++) {
            PhyScriptBinding row = rows.get(i);
            Body body = r.bodyAt(row.getBody());
            if (row.getScript() >= scripts.length) {
                r.unsupported(UnsupportedElement.Kind.SCRIPT_BINDING, i, BuildResult.missing("script", row.getScript(), scripts.length));
            } else if (body == null) {
                r.unsupported(UnsupportedElement.Kind.SCRIPT_BINDING, i,
                    BuildResult.missing("body", row.getBody(), document.getBodies().size()));
            } else {
                world.applyScript(scripts[row.getScript()], body);
            }
        }
    }

    /** A script in the engine's units: angular velocities and accelerations change sign (phy-mapping.md). */
    static Script script(PhyScript stored, int index, BuildResult r) {
        Script s = new Script(stored.isRestarting());
        for (PhyScriptElement e : stored.getElements()) {
            switch (e.getType()) {
                case PhyScriptElement.TYPE_NONE:
                    s.addElement(Script.NONE, 0f, e.getTicks());
                    break;
                case PhyScriptElement.TYPE_ANGLE:
                    s.addElement(e.getType(), PhyFixed.fx2(e.getARaw()), e.getTicks());
                    break;
                case PhyScriptElement.TYPE_ANGULAR_VELOCITY:
                case PhyScriptElement.TYPE_ANGULAR_ACCELERATION:
                    s.addElement(e.getType(), -PhyFixed.fx2(e.getARaw()), e.getTicks());
                    break;
                case PhyScriptElement.TYPE_POSITION:
                case PhyScriptElement.TYPE_VELOCITY:
                case PhyScriptElement.TYPE_ACCELERATION:
                    s.addElement(e.getType(), PhyFixed.fx(e.getARaw()), PhyFixed.fx(e.getBRaw()), e.getTicks());
                    break;
                default:
                    // The original's switch does nothing for a type it does not know.
                    s.addElement(Script.NONE, 0f, e.getTicks());
                    r.approximated(UnsupportedElement.Kind.SCRIPT, index, "element type " + e.getType()
                        + " is not defined (0 to 6): it does nothing, as in the original");
                    break;
            }
        }
        return s;
    }

    /** A script as the file stores it (the inverse of {@link #script}). */
    static PhyScript stored(Script s) {
        PhyScript p = new PhyScript();
        p.setRestartByte(s.isRestarting() ? 1 : 0);
        for (int i = 0; i < s.getElementCount(); i++) {
            int type = s.getType(i);
            int a;
            int b = 0;
            if (type == Script.ANGLE) {
                a = PhyFixed.toFx2(s.getA(i));
            } else if (type == Script.ANGULAR_VELOCITY || type == Script.ANGULAR_ACCELERATION) {
                a = PhyFixed.toFx2(-s.getA(i));
            } else {
                a = PhyFixed.toFx(s.getA(i));
                b = PhyFixed.toFx(s.getB(i));
            }
            p.getElements().add(new PhyScriptElement(type, a, b, s.getTicks(i)));
        }
        return p;
    }
}
