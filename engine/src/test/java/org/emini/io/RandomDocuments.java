package org.emini.io;

import java.nio.charset.StandardCharsets;
import java.util.Random;

/**
 * Random documents holding every record type, valid for their version word: fields a version does
 * not store keep their defaults, references name earlier records only.
 */
final class RandomDocuments {
    /** Version words at every boundary of the raw and masked tests, and odd ones the loader accepts. */
    static final int[] VERSION_WORDS = {0x01F0, 0x0100, 0x0200, 0x0201, 0x0300, 0x03FF, 0x0400, 0x04FF, 0x0500,
        0x0600, 0x0601, 0x0700, 0x0701, 0x0800, 0x0801, 0x0900, 0x0901, 0x0A00, 0x0A7F, 0x00010500, 0xFFFF0400};

    private RandomDocuments() {
    }

    static PhyWorld generate(Random r) {
        return generate(r, VERSION_WORDS[r.nextInt(VERSION_WORDS.length)]);
    }

    static PhyWorld generate(Random r, int v) {
        PhyWorld w = new PhyWorld(v);
        boolean tagged = PhyVersion.isTagged(v);
        int shapes = 1 + r.nextInt(6);
        for (int i = 0; i < shapes; i++) {
            if (i > 0 && PhyVersion.hasMultiShapes(v) && r.nextInt(4) == 0) {
                w.getShapes().add(multiShape(r, i));
            } else {
                w.getShapes().add(shape(r, v));
            }
        }
        int bodies = r.nextInt(7);
        for (int i = 0; i < bodies; i++) {
            w.getBodies().add(body(r, v, shapes));
        }
        if (tagged && r.nextBoolean()) {
            PhyLandscape l = new PhyLandscape();
            int n = r.nextInt(6);
            for (int i = 0; i < n; i++) {
                l.getSegments().add(new PhySegment(vector(r), vector(r), r.nextInt(4) == 0 ? r.nextInt(256) : r.nextInt(3)));
            }
            PhyShape material = shape(r, v);
            material.setVertices();
            l.setMaterial(material);
            w.setLandscape(l);
        }
        if (bodies > 0) {
            int n = r.nextInt(5);
            for (int i = 0; i < n; i++) {
                w.getConstraints().add(constraint(r, v, bodies));
            }
        }
        if (tagged && r.nextBoolean()) {
            int n = 1 + r.nextInt(3);
            for (int i = 0; i < n; i++) {
                PhyScript s = new PhyScript();
                s.setRestartByte(r.nextInt(3));
                int e = r.nextInt(4);
                for (int k = 0; k < e; k++) {
                    s.getElements().add(new PhyScriptElement(r.nextInt(8), r.nextInt(), r.nextInt(), r.nextInt(256)));
                }
                w.getScripts().add(s);
            }
            int rows = r.nextInt(4);
            for (int i = 0; i < rows; i++) {
                int body = bodies == 0 || r.nextInt(4) == 0 ? PhyWorld.NONE : r.nextInt(bodies);
                w.getScriptBindings().add(new PhyScriptBinding(r.nextInt(n), body));
            }
        }
        int events = r.nextInt(5);
        for (int i = 0; i < events; i++) {
            w.getEvents().add(event(r, v, w));
        }
        if (tagged && r.nextBoolean()) {
            int n = 1 + r.nextInt(3);
            for (int i = 0; i < n; i++) {
                w.getParticleEmitters().add(emitter(r, v, bodies));
            }
        }
        if (tagged && r.nextBoolean()) {
            PhyWorldSettings s = new PhyWorldSettings();
            s.setGravity(vector(r));
            s.setDampingLinearRaw(r.nextInt());
            s.setDampingRotationalRaw(PhyVersion.hasSeparateDamping(v) ? r.nextInt() : s.getDampingLinearRaw());
            userData(r, s, PhyVersion.othersHaveUserData(v));
            w.setSettings(s);
        }
        if (!tagged) {
            byte[] trailing = new byte[r.nextInt(3)];
            r.nextBytes(trailing);
            w.setTrailingBytes(trailing);
        }
        return w;
    }

    static PhyVector vector(Random r) {
        return r.nextBoolean() ? new PhyVector(r.nextInt(), r.nextInt())
                : new PhyVector((r.nextInt(2001) - 1000) << 12, (r.nextInt(2001) - 1000) << 12);
    }

    static void userData(Random r, PhyElement e, boolean stored) {
        if (!stored) {
            return;
        }
        switch (r.nextInt(4)) {
            case 0:
                break;
            case 1:
                e.setUserData("element=treasurespawn\nvalue=" + r.nextInt(1000));
                break;
            case 2:
                e.setUserData("ünïcødé ✓ " + new String(Character.toChars(0x1F600)));
                break;
            default:
                byte[] b = new byte[r.nextInt(9)];
                r.nextBytes(b);
                e.setUserDataBytes(b);
                break;
        }
    }

    static PhyShape shape(Random r, int v) {
        PhyShape s = new PhyShape();
        PhyVector[] vs = new PhyVector[r.nextInt(14)];
        for (int i = 0; i < vs.length; i++) {
            vs[i] = vector(r);
        }
        s.setVertices(vs);
        s.setElasticityRaw(r.nextInt(4097));
        s.setFrictionRaw(r.nextBoolean() ? r.nextInt(4097) : r.nextInt());
        if (PhyVersion.shapeHasMass(v)) {
            s.setMassRaw(r.nextInt());
        }
        if (PhyVersion.shapeHasLegacyId(v)) {
            s.setLegacyId(r.nextInt(256));
        }
        userData(r, s, PhyVersion.shapeAndBodyHaveUserData(v));
        return s;
    }

    static PhyMultiShape multiShape(Random r, int before) {
        int[] parts = new int[r.nextInt(4)];
        for (int i = 0; i < parts.length; i++) {
            parts[i] = r.nextInt(before);
        }
        PhyMultiShape m = new PhyMultiShape(parts);
        userData(r, m, true);
        return m;
    }

    static PhyBody body(Random r, int v, int shapes) {
        PhyBody b = new PhyBody();
        if (PhyVersion.bodyHasLegacyMass(v)) {
            b.setLegacyMassRaw(r.nextBoolean() ? 4096 : 16777217);
        }
        b.setPosition(vector(r));
        b.setVelocity(vector(r));
        b.setAngleRaw(r.nextInt());
        b.setAngularVelocityRaw(r.nextInt());
        b.setShapeIndex(r.nextInt(shapes));
        b.setFlags(r.nextInt(256));
        b.setCollisionLayers(r.nextInt());
        userData(r, b, PhyVersion.shapeAndBodyHaveUserData(v));
        return b;
    }

    static PhyConstraint constraint(Random r, int v, int bodies) {
        PhyConstraint c;
        switch (r.nextInt(3)) {
            case 0:
                PhyJoint j = new PhyJoint();
                j.setFixedByte(r.nextInt(3));
                c = pair(r, j, bodies);
                break;
            case 1:
                PhySpring s = new PhySpring();
                s.setRestLengthRaw(r.nextInt());
                s.setCoefficientRaw(r.nextInt());
                c = pair(r, s, bodies);
                break;
            default:
                PhyMotor m = new PhyMotor();
                m.setBody(r.nextInt(bodies));
                m.setTargetARaw(r.nextInt());
                m.setTargetBRaw(r.nextInt());
                m.setMaxForceRaw(r.nextInt());
                m.setFlags(r.nextInt(8));
                c = m;
                break;
        }
        userData(r, c, PhyVersion.othersHaveUserData(v));
        return c;
    }

    private static PhyConstraint pair(Random r, PhyPairConstraint c, int bodies) {
        c.setBody1(r.nextInt(bodies));
        c.setAnchor1(vector(r));
        c.setBody2(r.nextInt(bodies));
        c.setAnchor2(vector(r));
        return c;
    }

    static PhyEvent event(Random r, int v, PhyWorld soFar) {
        PhyEvent e = new PhyEvent();
        int[] types = {0, 1, 2, 3, 4, 5, 6, 10, 77};
        e.setType(types[r.nextInt(types.length)]);
        int bodies = soFar.getBodies().size();
        e.setBodyFilter(bodies == 0 || r.nextBoolean() ? PhyWorld.NONE : r.nextInt(bodies));
        e.setShapeFilter(r.nextBoolean() ? PhyWorld.NONE : r.nextInt(soFar.getShapes().size()));
        if (PhyVersion.eventHasLegacyId(v)) {
            e.setLegacyId(r.nextInt(256));
        } else {
            e.setTriggerOnceByte(r.nextInt(3));
            int constraints = soFar.getConstraints().size();
            e.setConstraintFilter(constraints == 0 || r.nextBoolean() ? PhyWorld.NONE : r.nextInt(constraints));
        }
        for (int i = 0; i < 4; i++) {
            e.setTargetRaw(i, r.nextInt());
        }
        if (e.getType() == PhyEvent.TYPE_BODY_SENSOR) {
            e.setSensor(body(r, v, soFar.getShapes().size()));
        }
        userData(r, e, PhyVersion.othersHaveUserData(v));
        return e;
    }

    static PhyParticleEmitter emitter(Random r, int v, int bodies) {
        PhyParticleEmitter p = new PhyParticleEmitter();
        p.setBody(bodies == 0 || r.nextBoolean() ? PhyWorld.NONE : r.nextInt(bodies));
        p.setAxesFixedByte(r.nextInt(3));
        p.setPosition1(vector(r));
        p.setPosition2(vector(r));
        p.setEmitAngleRaw(r.nextInt());
        p.setEmitAngleSpreadRaw(r.nextInt());
        p.setSpeedRaw(r.nextInt());
        p.setSpeedSpreadRaw(r.nextInt());
        p.setRateRaw(r.nextInt());
        p.setRateSpreadRaw(r.nextInt());
        p.setLifetimeRaw(r.nextInt());
        p.setLifetimeSpreadRaw(r.nextInt());
        p.setMaxParticles(r.nextInt());
        p.setElasticityRaw(r.nextInt());
        p.setGravityFactorRaw(r.nextInt());
        p.setDampingRaw(r.nextInt());
        userData(r, p, PhyVersion.othersHaveUserData(v));
        return p;
    }

    /** Bytes as a short string for failure messages. */
    static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < Math.min(b.length, 64); i++) {
            s.append(String.format("%02x", b[i] & 0xFF));
        }
        return b.length > 64 ? s + "… (" + b.length + " bytes)" : s.toString();
    }

    static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }
}
