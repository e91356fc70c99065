package org.emini.designer;

import java.util.List;

import org.emini.io.PhyBody;
import org.emini.io.PhyConstraint;
import org.emini.io.PhyEvent;
import org.emini.io.PhyJoint;
import org.emini.io.PhyLandscape;
import org.emini.io.PhyMotor;
import org.emini.io.PhyMultiShape;
import org.emini.io.PhyPairConstraint;
import org.emini.io.PhyParticleEmitter;
import org.emini.io.PhySegment;
import org.emini.io.PhyShape;
import org.emini.io.PhyShapeBase;
import org.emini.io.PhySpring;
import org.emini.io.PhyVector;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWorldSettings;

/**
 * The page's document: a world file ({@link PhyWorld}) as JSON with the records' raw integer fields
 * (positions in 1/4096 px, angles in 2⁻²⁴ rad, materials in 1/4096; see phy-mapping.md in
 * org.emini.io), so the page edits exactly what a <code>.phy</code> file holds and the text
 * crosses the bridge without rounding. {@link #write} and {@link #read} are inverse on every record
 * the page edits; scripts are not in the document (they stay with the file they came from).
 */
final class DocJson {
    private DocJson() {
    }

    /**
     * The document of a world file.
     *
     * @param w the world file
     * @return its JSON
     */
    static String write(PhyWorld w) {
        StringBuilder sb = new StringBuilder(4096);
        sb.append("{\"version\":").append(w.getVersionWord());
        PhyWorldSettings s = w.getSettings();
        if (s != null) {
            sb.append(",\"settings\":{\"gravity\":");
            vector(sb, s.getGravity());
            sb.append(",\"dampingLinear\":").append(s.getDampingLinearRaw())
                    .append(",\"dampingRotational\":").append(s.getDampingRotationalRaw()).append('}');
        }
        sb.append(",\"shapes\":[");
        List<PhyShapeBase> shapes = w.getShapes();
        for (int i = 0; i < shapes.size(); i++) {
            sep(sb, i);
            PhyShapeBase base = shapes.get(i);
            if (base.isMultiShape()) {
                sb.append("{\"kind\":\"multi\",\"parts\":");
                ints(sb, ((PhyMultiShape) base).getParts());
                sb.append('}');
            } else {
                shape(sb, (PhyShape) base);
            }
        }
        sb.append("],\"bodies\":[");
        List<PhyBody> bodies = w.getBodies();
        for (int i = 0; i < bodies.size(); i++) {
            sep(sb, i);
            body(sb, bodies.get(i));
        }
        sb.append("],\"constraints\":[");
        List<PhyConstraint> constraints = w.getConstraints();
        for (int i = 0; i < constraints.size(); i++) {
            sep(sb, i);
            constraint(sb, constraints.get(i));
        }
        sb.append(']');
        PhyLandscape land = w.getLandscape();
        if (land != null) {
            sb.append(",\"landscape\":{\"segments\":[");
            List<PhySegment> segs = land.getSegments();
            for (int i = 0; i < segs.size(); i++) {
                sep(sb, i);
                PhySegment g = segs.get(i);
                sb.append('[').append(g.getStart().getXRaw()).append(',').append(g.getStart().getYRaw()).append(',')
                        .append(g.getEnd().getXRaw()).append(',').append(g.getEnd().getYRaw()).append(',')
                        .append(g.getFace()).append(']');
            }
            sb.append("],\"material\":");
            shape(sb, land.getMaterial());
            sb.append('}');
        }
        sb.append(",\"events\":[");
        List<PhyEvent> events = w.getEvents();
        for (int i = 0; i < events.size(); i++) {
            sep(sb, i);
            event(sb, events.get(i));
        }
        sb.append("],\"emitters\":[");
        List<PhyParticleEmitter> emitters = w.getParticleEmitters();
        for (int i = 0; i < emitters.size(); i++) {
            sep(sb, i);
            emitter(sb, emitters.get(i));
        }
        sb.append("],\"scripts\":").append(w.getScripts().size()).append('}');
        return sb.toString();
    }

    /**
     * A world file from a document; scripts and script bindings are taken from {@code scriptsFrom} when
     * the document came from it (its "scripts" count is that file's).
     *
     * @param json the document
     * @param scriptsFrom the world file whose scripts to keep, or null
     * @return the world file
     * @throws IllegalArgumentException naming the field that is missing or wrong
     */
    static PhyWorld read(String json, PhyWorld scriptsFrom) {
        Doc d = new Doc(Json.parse(json), "document");
        PhyWorld w = new PhyWorld(d.integer("version", new PhyWorld().getVersionWord()));
        if (d.has("settings")) {
            Doc s = d.object("settings");
            PhyWorldSettings ws = new PhyWorldSettings();
            ws.setGravity(vector(s, "gravity"));
            ws.setDampingLinearRaw(s.integer("dampingLinear", 0));
            ws.setDampingRotationalRaw(s.integer("dampingRotational", 0));
            w.setSettings(ws);
        }
        List<?> shapes = d.list("shapes");
        for (int i = 0; i < shapes.size(); i++) {
            Doc s = new Doc(shapes.get(i), "shapes[" + i + "]");
            if ("multi".equals(s.string("kind"))) {
                w.getShapes().add(new PhyMultiShape(s.integers("parts")));
            } else {
                w.getShapes().add(shape(s));
            }
        }
        List<?> bodies = d.list("bodies");
        for (int i = 0; i < bodies.size(); i++) {
            w.getBodies().add(body(new Doc(bodies.get(i), "bodies[" + i + "]")));
        }
        List<?> constraints = d.list("constraints");
        for (int i = 0; i < constraints.size(); i++) {
            w.getConstraints().add(constraint(new Doc(constraints.get(i), "constraints[" + i + "]")));
        }
        if (d.has("landscape")) {
            Doc l = d.object("landscape");
            PhyLandscape land = new PhyLandscape();
            List<?> segs = l.list("segments");
            for (int i = 0; i < segs.size(); i++) {
                Doc holder = new Doc(java.util.Collections.singletonMap("s", segs.get(i)), l.where() + ".segments[" + i + "]");
                int[] v = holder.integers("s");
                if (v.length != 5) {
                    throw new IllegalArgumentException(l.where() + ".segments[" + i + "]: expected [x1, y1, x2, y2, face]");
                }
                land.getSegments().add(new PhySegment(new PhyVector(v[0], v[1]), new PhyVector(v[2], v[3]), v[4]));
            }
            if (l.has("material")) {
                land.setMaterial(shape(l.object("material")));
            }
            w.setLandscape(land);
        }
        List<?> events = d.list("events");
        for (int i = 0; i < events.size(); i++) {
            w.getEvents().add(event(new Doc(events.get(i), "events[" + i + "]")));
        }
        List<?> emitters = d.list("emitters");
        for (int i = 0; i < emitters.size(); i++) {
            w.getParticleEmitters().add(emitter(new Doc(emitters.get(i), "emitters[" + i + "]")));
        }
        // Only a document that came from that file (it counts the file's scripts) keeps them.
        if (scriptsFrom != null && d.integer("scripts", 0) > 0 && d.integer("scripts", 0) == scriptsFrom.getScripts().size()) {
            w.getScripts().addAll(scriptsFrom.getScripts());
            w.getScriptBindings().addAll(scriptsFrom.getScriptBindings());
        }
        return w;
    }

    private static void shape(StringBuilder sb, PhyShape s) {
        sb.append("{\"kind\":\"").append(s.isCircle() ? "circle" : "polygon").append("\",\"vertices\":[");
        for (int i = 0; i < s.getVertexCount(); i++) {
            sep(sb, i);
            sb.append(s.getVertex(i).getXRaw()).append(',').append(s.getVertex(i).getYRaw());
        }
        sb.append("],\"elasticity\":").append(s.getElasticityRaw()).append(",\"friction\":").append(s.getFrictionRaw())
                .append(",\"mass\":").append(s.getMassRaw()).append(",\"legacyId\":").append(s.getLegacyId())
                .append(",\"userData\":");
        Json.quote(sb, s.getUserData());
        sb.append('}');
    }

    private static PhyShape shape(Doc s) {
        int[] xy = s.integers("vertices");
        if (xy.length % 2 != 0) {
            throw new IllegalArgumentException(s.where() + ".vertices: an odd count of coordinates");
        }
        PhyVector[] v = new PhyVector[xy.length / 2];
        for (int i = 0; i < v.length; i++) {
            v[i] = new PhyVector(xy[2 * i], xy[2 * i + 1]);
        }
        PhyShape shape = new PhyShape(v);
        shape.setElasticityRaw(s.integer("elasticity", 0));
        shape.setFrictionRaw(s.integer("friction", 1024));
        shape.setMassRaw(s.integer("mass", 4096));
        shape.setLegacyId(s.integer("legacyId", 0));
        shape.setUserData(s.string("userData"));
        return shape;
    }

    private static void body(StringBuilder sb, PhyBody b) {
        sb.append("{\"shape\":").append(b.getShapeIndex()).append(",\"position\":");
        vector(sb, b.getPosition());
        sb.append(",\"velocity\":");
        vector(sb, b.getVelocity());
        sb.append(",\"angle\":").append(b.getAngleRaw()).append(",\"angularVelocity\":").append(b.getAngularVelocityRaw())
                .append(",\"flags\":").append(b.getFlags()).append(",\"layers\":").append(b.getCollisionLayers())
                .append(",\"legacyMass\":").append(b.getLegacyMassRaw()).append(",\"userData\":");
        Json.quote(sb, b.getUserData());
        sb.append('}');
    }

    private static PhyBody body(Doc d) {
        PhyBody b = new PhyBody();
        b.setShapeIndex(d.integer("shape"));
        b.setPosition(vector(d, "position"));
        b.setVelocity(d.has("velocity") ? vector(d, "velocity") : PhyVector.ZERO);
        b.setAngleRaw(d.integer("angle", 0));
        b.setAngularVelocityRaw(d.integer("angularVelocity", 0));
        b.setFlags(d.integer("flags", PhyBody.FLAG_DYNAMIC | PhyBody.FLAG_ROTATES));
        b.setCollisionLayers(d.integer("layers", 1));
        b.setLegacyMassRaw(d.integer("legacyMass", 0));
        b.setUserData(d.string("userData"));
        return b;
    }

    private static void constraint(StringBuilder sb, PhyConstraint c) {
        if (c instanceof PhyMotor) {
            PhyMotor m = (PhyMotor) c;
            sb.append("{\"kind\":\"motor\",\"body\":").append(m.getBody()).append(",\"targetA\":").append(m.getTargetARaw())
                    .append(",\"targetB\":").append(m.getTargetBRaw()).append(",\"maxForce\":").append(m.getMaxForceRaw())
                    .append(",\"flags\":").append(m.getFlags());
        } else {
            PhyPairConstraint p = (PhyPairConstraint) c;
            sb.append("{\"kind\":\"").append(c instanceof PhySpring ? "spring" : "joint").append("\",\"body1\":")
                    .append(p.getBody1()).append(",\"anchor1\":");
            vector(sb, p.getAnchor1());
            sb.append(",\"body2\":").append(p.getBody2()).append(",\"anchor2\":");
            vector(sb, p.getAnchor2());
            if (c instanceof PhySpring) {
                PhySpring s = (PhySpring) c;
                sb.append(",\"restLength\":").append(s.getRestLengthRaw()).append(",\"coefficient\":").append(s.getCoefficientRaw());
            } else {
                sb.append(",\"fixed\":").append(((PhyJoint) c).getFixedByte());
            }
        }
        sb.append(",\"userData\":");
        Json.quote(sb, c.getUserData());
        sb.append('}');
    }

    private static PhyConstraint constraint(Doc d) {
        String kind = d.string("kind");
        PhyConstraint c;
        if ("motor".equals(kind)) {
            PhyMotor m = new PhyMotor();
            m.setBody(d.integer("body"));
            m.setTargetARaw(d.integer("targetA", 0));
            m.setTargetBRaw(d.integer("targetB", 0));
            m.setMaxForceRaw(d.integer("maxForce", 0));
            m.setFlags(d.integer("flags", 0));
            c = m;
        } else if ("spring".equals(kind) || "joint".equals(kind)) {
            PhyPairConstraint p;
            if ("spring".equals(kind)) {
                PhySpring s = new PhySpring();
                s.setRestLengthRaw(d.integer("restLength", 0));
                s.setCoefficientRaw(d.integer("coefficient", 0));
                p = s;
            } else {
                PhyJoint j = new PhyJoint();
                j.setFixedByte(d.integer("fixed", 0));
                p = j;
            }
            p.setBody1(d.integer("body1"));
            p.setAnchor1(vector(d, "anchor1"));
            p.setBody2(d.integer("body2"));
            p.setAnchor2(vector(d, "anchor2"));
            c = p;
        } else {
            throw new IllegalArgumentException(d.where() + ".kind: expected joint, spring or motor, was '" + kind + "'");
        }
        c.setUserData(d.string("userData"));
        return c;
    }

    private static void event(StringBuilder sb, PhyEvent e) {
        sb.append("{\"type\":").append(e.getType()).append(",\"legacyId\":").append(e.getLegacyId())
                .append(",\"triggerOnce\":").append(e.getTriggerOnceByte()).append(",\"bodyFilter\":").append(e.getBodyFilter())
                .append(",\"shapeFilter\":").append(e.getShapeFilter()).append(",\"constraintFilter\":")
                .append(e.getConstraintFilter()).append(",\"targets\":[").append(e.getTargetRaw(0)).append(',')
                .append(e.getTargetRaw(1)).append(',').append(e.getTargetRaw(2)).append(',').append(e.getTargetRaw(3)).append(']');
        if (e.getSensor() != null) {
            sb.append(",\"sensor\":");
            body(sb, e.getSensor());
        }
        sb.append(",\"userData\":");
        Json.quote(sb, e.getUserData());
        sb.append('}');
    }

    private static PhyEvent event(Doc d) {
        PhyEvent e = new PhyEvent();
        e.setType(d.integer("type"));
        e.setLegacyId(d.integer("legacyId", 0));
        e.setTriggerOnceByte(d.integer("triggerOnce", 0));
        e.setBodyFilter(d.integer("bodyFilter", PhyWorld.NONE));
        e.setShapeFilter(d.integer("shapeFilter", PhyWorld.NONE));
        e.setConstraintFilter(d.integer("constraintFilter", PhyWorld.NONE));
        int[] t = d.integers("targets");
        for (int i = 0; i < 4; i++) {
            e.setTargetRaw(i, i < t.length ? t[i] : 0);
        }
        if (d.has("sensor")) {
            e.setSensor(body(d.object("sensor")));
        }
        e.setUserData(d.string("userData"));
        return e;
    }

    private static void emitter(StringBuilder sb, PhyParticleEmitter p) {
        sb.append("{\"body\":").append(p.getBody()).append(",\"axesFixed\":").append(p.getAxesFixedByte())
                .append(",\"position1\":");
        vector(sb, p.getPosition1());
        sb.append(",\"position2\":");
        vector(sb, p.getPosition2());
        sb.append(",\"emitAngle\":").append(p.getEmitAngleRaw()).append(",\"emitAngleSpread\":").append(p.getEmitAngleSpreadRaw())
                .append(",\"speed\":").append(p.getSpeedRaw()).append(",\"speedSpread\":").append(p.getSpeedSpreadRaw())
                .append(",\"rate\":").append(p.getRateRaw()).append(",\"rateSpread\":").append(p.getRateSpreadRaw())
                .append(",\"lifetime\":").append(p.getLifetimeRaw()).append(",\"lifetimeSpread\":").append(p.getLifetimeSpreadRaw())
                .append(",\"maxParticles\":").append(p.getMaxParticles()).append(",\"elasticity\":").append(p.getElasticityRaw())
                .append(",\"gravityFactor\":").append(p.getGravityFactorRaw()).append(",\"damping\":").append(p.getDampingRaw())
                .append(",\"userData\":");
        Json.quote(sb, p.getUserData());
        sb.append('}');
    }

    private static PhyParticleEmitter emitter(Doc d) {
        PhyParticleEmitter p = new PhyParticleEmitter();
        p.setBody(d.integer("body", PhyWorld.NONE));
        p.setAxesFixedByte(d.integer("axesFixed", 0));
        p.setPosition1(vector(d, "position1"));
        p.setPosition2(d.has("position2") ? vector(d, "position2") : vector(d, "position1"));
        p.setEmitAngleRaw(d.integer("emitAngle", 0));
        p.setEmitAngleSpreadRaw(d.integer("emitAngleSpread", 0));
        p.setSpeedRaw(d.integer("speed", 0));
        p.setSpeedSpreadRaw(d.integer("speedSpread", 0));
        p.setRateRaw(d.integer("rate", 0));
        p.setRateSpreadRaw(d.integer("rateSpread", 0));
        p.setLifetimeRaw(d.integer("lifetime", 0));
        p.setLifetimeSpreadRaw(d.integer("lifetimeSpread", 0));
        p.setMaxParticles(d.integer("maxParticles", 0));
        p.setElasticityRaw(d.integer("elasticity", 0));
        p.setGravityFactorRaw(d.integer("gravityFactor", 4096));
        p.setDampingRaw(d.integer("damping", 0));
        p.setUserData(d.string("userData"));
        return p;
    }

    private static void vector(StringBuilder sb, PhyVector v) {
        sb.append('[').append(v.getXRaw()).append(',').append(v.getYRaw()).append(']');
    }

    private static PhyVector vector(Doc d, String key) {
        int[] v = d.integers(key);
        if (v.length != 2) {
            throw new IllegalArgumentException(d.where() + "." + key + ": expected [x, y]");
        }
        return new PhyVector(v[0], v[1]);
    }

    private static void ints(StringBuilder sb, int[] v) {
        sb.append('[');
        for (int i = 0; i < v.length; i++) {
            sep(sb, i);
            sb.append(v[i]);
        }
        sb.append(']');
    }

    private static void sep(StringBuilder sb, int i) {
        if (i > 0) {
            sb.append(',');
        }
    }
}
