package org.emini.dynamics;

import java.util.Arrays;
import org.emini.internal.HeapSort;

import static org.emini.dynamics.ContactSolver.BASE_SEP;
import static org.emini.dynamics.ContactSolver.BLOCK;
import static org.emini.dynamics.ContactSolver.BODY_A;
import static org.emini.dynamics.ContactSolver.BODY_B;
import static org.emini.dynamics.ContactSolver.CI;
import static org.emini.dynamics.ContactSolver.CIRCLE_A;
import static org.emini.dynamics.ContactSolver.CIRCLE_B;
import static org.emini.dynamics.ContactSolver.CS;
import static org.emini.dynamics.ContactSolver.FRICTION;
import static org.emini.dynamics.ContactSolver.K11;
import static org.emini.dynamics.ContactSolver.K12;
import static org.emini.dynamics.ContactSolver.K22;
import static org.emini.dynamics.ContactSolver.MAXIMP;
import static org.emini.dynamics.ContactSolver.NIMP;
import static org.emini.dynamics.ContactSolver.NMASS;
import static org.emini.dynamics.ContactSolver.NX;
import static org.emini.dynamics.ContactSolver.NY;
import static org.emini.dynamics.ContactSolver.P0;
import static org.emini.dynamics.ContactSolver.POINTS;
import static org.emini.dynamics.ContactSolver.PS;
import static org.emini.dynamics.ContactSolver.RAX;
import static org.emini.dynamics.ContactSolver.RAY;
import static org.emini.dynamics.ContactSolver.RBX;
import static org.emini.dynamics.ContactSolver.RBY;
import static org.emini.dynamics.ContactSolver.RELVEL;
import static org.emini.dynamics.ContactSolver.RESTITUTION;
import static org.emini.dynamics.ContactSolver.SHIFT;
import static org.emini.dynamics.ContactSolver.TIMP;
import static org.emini.dynamics.ContactSolver.TMASS;
import static org.emini.dynamics.ContactSolver.commonPointShift;
import static org.emini.dynamics.SolverBodies.DPX;
import static org.emini.dynamics.SolverBodies.DPY;
import static org.emini.dynamics.SolverBodies.DQC;
import static org.emini.dynamics.SolverBodies.DQS;
import static org.emini.dynamics.SolverBodies.II;
import static org.emini.dynamics.SolverBodies.IM;
import static org.emini.dynamics.SolverBodies.STRIDE;
import static org.emini.dynamics.SolverBodies.VX;
import static org.emini.dynamics.SolverBodies.VY;
import static org.emini.dynamics.SolverBodies.W;

/**
 * Elastic impacts as pairwise collisions, on {@link ContactSolver}'s constraint layout, at the start of
 * each substep (see {@link #run}).
 */
final class ElasticImpacts {
    /** Most sweeps of {@link #run}: a row is passed down in two whatever its order, a pinched body never stops. */
    private static final int SWEEPS = 16;
    // Slots of the contacts with elasticity, in slot order: the only ones the sweeps visit.
    private int[] elastic = new int[16];
    private int count;
    // The contacts a sweep of this substep first touched: contact index (high half) and slot.
    private long[] touched = new long[16];

    /** Keeps the slots, of the first {@code slots}, whose contact has elasticity. */
    void collect(float[] f, int slots) {
        count = 0;
        for (int k = 0; k < slots; k++) {
            if (f[k * CS + RESTITUTION] != 0f) {
                if (count == elastic.length) {
                    int[] grown = new int[2 * elastic.length];
                    System.arraycopy(elastic, 0, grown, 0, count);
                    elastic = grown;
                }
                elastic[count++] = k;
            }
        }
    }

    /**
     * The substep's elastic impacts, before its warm start. A point of an elastic contact that is not
     * pushing already, approaches faster than the threshold and would close within the substep takes
     * the impulse that sends it apart at e times its approach speed, with friction bounded by that
     * impulse: a pairwise collision (Newton's law of restitution). Sweeps, alternately forward and
     * backward, until no point is left to bounce: the impulse given to the next body of a row of
     * touching bodies is that body's impact, so the row passes the velocity down as a chain of
     * pairwise collisions does (Newton's cradle), and no impulse can add energy. A bounce aimed after
     * the solve at the approach a contact was first seen at instead made the last balls of a row
     * leave together (e = 1: energy from 0.49 to 7.8 times the impact's). Resting contacts keep
     * their warm-started impulse and are left to the solve, as are the points still approaching
     * after the last sweep (a ball pinched between two walls).
     */
    void run(float[] f, int[] n, Contact[] contacts, int[] contactOf, SolverBodies bodies, float h, float threshold,
            float slop, StepData step) {
        if (count == 0) {
            return;
        }
        int began = 0;
        for (int sweep = 0; sweep < SWEEPS; sweep++) {
            boolean forward = (sweep & 1) == 0;
            boolean bounced = false;
            for (int i = 0; i < count; i++) {
                int k = elastic[forward ? i : count - 1 - i];
                if (impact(f, n, bodies, k, h, threshold, slop)) {
                    bounced = true;
                    // A bounce is a touch, although the points turn back just short of closing.
                    Contact c = contacts[k];
                    if (!c.touching) {
                        c.touching = true;
                        if (began == touched.length) {
                            touched = Arrays.copyOf(touched, 2 * began);
                        }
                        touched[began++] = (long) contactOf[k] << 32 | k;
                    }
                }
            }
            if (!bounced) {
                break;
            }
        }
        // Listed in the contacts' order, as the narrowphase lists its own, not in slot order: the
        // slots' order depends on how threads share the solve (SolveIslands).
        HeapSort.sort(touched, began);
        for (int i = 0; i < began; i++) {
            step.contactBegan(contacts[(int) touched[i]]);
        }
    }

    /** One contact's impact (see {@link #run}); true when a point bounced. */
    private static boolean impact(float[] f, int[] n, SolverBodies bodies, int k, float h, float threshold,
            float slop) {
        float[] st = bodies.state;
        int fo = k * CS;
        int io = k * CI;
        int oa = n[io + BODY_A] * STRIDE;
        int ob = n[io + BODY_B] * STRIDE;
        float nx = f[fo + NX];
        float ny = f[fo + NY];
        float mA = st[oa + IM];
        float iA = st[oa + II];
        float mB = st[ob + IM];
        float iB = st[ob + II];
        float vax = st[oa + VX];
        float vay = st[oa + VY];
        float wa = st[oa + W];
        float vbx = st[ob + VX];
        float vby = st[ob + VY];
        float wb = st[ob + W];
        float dpx = st[ob + DPX] - st[oa + DPX];
        float dpy = st[ob + DPY] - st[oa + DPY];
        float qac = st[oa + DQC];
        float qas = st[oa + DQS];
        float qbc = st[ob + DQC];
        float qbs = st[ob + DQS];
        float circle = f[fo + CIRCLE_A] * qac - f[fo + CIRCLE_B] * qbc;
        // Dynamic pairs: impulses at the common point, as in the passes.
        float sx = commonPointShift(dpx, f[fo + SHIFT]);
        float sy = commonPointShift(dpy, f[fo + SHIFT]);
        int pc = n[io + POINTS];
        // The velocities the points' warm start would give (both points and friction together: a
        // face's two impulses each move the other point too).
        float uax = vax;
        float uay = vay;
        float uwa = wa;
        float ubx = vbx;
        float uby = vby;
        float uwb = wb;
        for (int p = 0; p < pc; p++) {
            int po = fo + P0 + p * PS;
            float ni = f[po + NIMP];
            float ti = f[po + TIMP];
            float px = ni * nx - ti * ny;
            float py = ni * ny + ti * nx;
            uax -= mA * px;
            uay -= mA * py;
            uwa -= iA * ((f[po + RAX] + sx) * py - (f[po + RAY] + sy) * px);
            ubx += mB * px;
            uby += mB * py;
            uwb += iB * ((f[po + RBX] - sx) * py - (f[po + RBY] - sy) * px);
        }
        // Which points bounce, and the separating speed each is sent apart at.
        boolean hit1 = false;
        boolean hit2 = false;
        float approach1 = 0f;
        float approach2 = 0f;
        // When within the substep the first bouncing point closes its gap.
        float contactTime = h;
        float e = f[fo + RESTITUTION];
        for (int p = 0; p < pc; p++) {
            int po = fo + P0 + p * PS;
            float rax = f[po + RAX];
            float ray = f[po + RAY];
            float rbx = f[po + RBX];
            float rby = f[po + RBY];
            float sep = (dpx + qbc * rbx - qbs * rby - qac * rax + qas * ray) * nx
                + (dpy + qbs * rbx + qbc * rby - qas * rax - qac * ray) * ny + circle + f[po + BASE_SEP];
            rax += sx;
            ray += sy;
            rbx -= sx;
            rby -= sy;
            float vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny;
            // The relative speed the warm start will add at this point.
            float warm = (ubx - uwb * rby - uax + uwa * ray) * nx + (uby + uwb * rbx - uay - uwa * rax) * ny - vn;
            float approach;
            if (sep > 0f) {
                // Apart: a stored impulse is the last relax pass slowing the point to close the gap
                // exactly in this substep; the approach is the speed it had before.
                approach = vn - warm;
                // Within the slop counts as closing: a gap closed exactly leaves the bodies touching,
                // and a touching point takes the solve's impulse before the next substep sees it.
                if (sep + approach * h > slop) {
                    continue;
                }
            } else {
                // Touching: a resting point's warm start takes back what gravity added this substep;
                // it is an impact only if more than the threshold is left.
                if (vn + warm > -threshold) {
                    continue;
                }
                approach = vn;
            }
            if (approach > -threshold) {
                continue;
            }
            float closes = sep > 0f ? sep / -approach : 0f;
            if (closes < contactTime) {
                contactTime = closes;
            }
            if (p == 0) {
                hit1 = true;
                approach1 = approach;
            } else {
                hit2 = true;
                approach2 = approach;
            }
        }
        if (!hit1 && !hit2) {
            return false;
        }
        float friction = f[fo + FRICTION];
        float d1 = 0f;
        float d2 = 0f;
        boolean solved = false;
        if (hit1 && hit2 && f[fo + BLOCK] != 0f) {
            // A face lands as a whole: both points together, or the body would spin.
            int p1 = fo + P0;
            int p2 = p1 + PS;
            float r1ax = f[p1 + RAX] + sx;
            float r1ay = f[p1 + RAY] + sy;
            float r1bx = f[p1 + RBX] - sx;
            float r1by = f[p1 + RBY] - sy;
            float r2ax = f[p2 + RAX] + sx;
            float r2ay = f[p2 + RAY] + sy;
            float r2bx = f[p2 + RBX] - sx;
            float r2by = f[p2 + RBY] - sy;
            float g1 = -e * approach1 - ((vbx - wb * r1by - vax + wa * r1ay) * nx + (vby + wb * r1bx - vay - wa * r1ax) * ny);
            float g2 = -e * approach2 - ((vbx - wb * r2by - vax + wa * r2ay) * nx + (vby + wb * r2bx - vay - wa * r2ax) * ny);
            float x1 = f[fo + K11] * g1 + f[fo + K12] * g2;
            float x2 = f[fo + K12] * g1 + f[fo + K22] * g2;
            if (x1 >= 0f && x2 >= 0f) {
                solved = true;
                d1 = x1;
                d2 = x2;
                float px = (d1 + d2) * nx;
                float py = (d1 + d2) * ny;
                vax -= mA * px;
                vay -= mA * py;
                wa -= iA * ((r1ax * ny - r1ay * nx) * d1 + (r2ax * ny - r2ay * nx) * d2);
                vbx += mB * px;
                vby += mB * py;
                wb += iB * ((r1bx * ny - r1by * nx) * d1 + (r2bx * ny - r2by * nx) * d2);
            }
        }
        for (int p = 0; p < pc && !solved; p++) {
            if (p == 0 ? !hit1 : !hit2) {
                continue;
            }
            int po = fo + P0 + p * PS;
            float rax = f[po + RAX] + sx;
            float ray = f[po + RAY] + sy;
            float rbx = f[po + RBX] - sx;
            float rby = f[po + RBY] - sy;
            // The first point's impulse may already have sent the second one apart.
            float vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny;
            float target = -e * (p == 0 ? approach1 : approach2);
            float d = vn < target ? (target - vn) * f[po + NMASS] : 0f;
            if (p == 0) {
                d1 = d;
            } else {
                d2 = d;
            }
            float px = d * nx;
            float py = d * ny;
            vax -= mA * px;
            vay -= mA * py;
            wa -= iA * (rax * py - ray * px);
            vbx += mB * px;
            vby += mB * py;
            wb += iB * (rbx * py - rby * px);
        }
        for (int p = 0; p < pc; p++) {
            float d = p == 0 ? d1 : d2;
            if (d == 0f) {
                continue;
            }
            int po = fo + P0 + p * PS;
            float rax = f[po + RAX] + sx;
            float ray = f[po + RAY] + sy;
            float rbx = f[po + RBX] - sx;
            float rby = f[po + RBY] - sy;
            float vt = -(vbx - wb * rby - vax + wa * ray) * ny + (vby + wb * rbx - vay - wa * rax) * nx;
            float maxF = friction * d;
            float t = -f[po + TMASS] * vt;
            t = t < -maxF ? -maxF : (t > maxF ? maxF : t);
            float px = -t * ny;
            float py = t * nx;
            vax -= mA * px;
            vay -= mA * py;
            wa -= iA * (rax * py - ray * px);
            vbx += mB * px;
            vby += mB * py;
            wb += iB * (rbx * py - rby * px);
            // For the hit events: the fastest approach of a point that took an impulse this tick.
            float vn = p == 0 ? approach1 : approach2;
            if (f[po + MAXIMP] == 0f || vn < f[po + RELVEL]) {
                f[po + RELVEL] = vn;
            }
            if (d > f[po + MAXIMP]) {
                f[po + MAXIMP] = d;
            }
            // The bounce replaces the point's warm start, which would otherwise push it apart again.
            f[po + NIMP] = 0f;
            f[po + TIMP] = 0f;
        }
        // Until the gap closes the bodies keep their old velocities (still in st): the bounce is taken
        // at the substep's start, so each owes the difference times that time (one substep early, a
        // head-on collision closing on a tick boundary ended 1 px from its closed form).
        if (contactTime > 0f) {
            if (oa != 0 && mA != 0f) {
                bodies.owe(oa / STRIDE, (st[oa + VX] - vax) * contactTime, (st[oa + VY] - vay) * contactTime, (st[oa + W] - wa) * contactTime);
            }
            if (ob != 0 && mB != 0f) {
                bodies.owe(ob / STRIDE, (st[ob + VX] - vbx) * contactTime, (st[ob + VY] - vby) * contactTime, (st[ob + W] - wb) * contactTime);
            }
        }
        if (oa != 0) {
            st[oa + VX] = vax;
            st[oa + VY] = vay;
            st[oa + W] = wa;
        }
        if (ob != 0) {
            st[ob + VX] = vbx;
            st[ob + VY] = vby;
            st[ob + W] = wb;
        }
        return true;
    }
}
