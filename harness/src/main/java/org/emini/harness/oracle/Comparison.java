package org.emini.harness.oracle;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.emini.harness.closedform.ClosedForm;
import org.emini.harness.metrics.PenetrationPair;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.ActionSpec;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.ExpectationSpec;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;

/**
 * Compares one scene's engine trace with its oracle trace, and both with the truth where the scene has
 * one: its closed-form model, or a law that holds for the scene (rigid bodies do not overlap, walls are
 * not passed, joints hold, an isolated system keeps its momentum, a system without contact or friction
 * keeps its energy). The rules are in scenarios/README.md (Comparison with the oracle).
 */
public final class Comparison {
    /** Figures of metric channels (penetration.points is left out: its count depends on manifold design). */
    private static final List<String[]> METRIC_FIGURES = List.of(
            new String[] {"energy.total", "maxDrift"},
            new String[] {"energy.kinetic", "final"},
            new String[] {"energy.potential", "final"},
            new String[] {"momentum.x", "maxDrift"},
            new String[] {"momentum.y", "maxDrift"},
            new String[] {"angularMomentum", "maxDrift"},
            new String[] {"penetration.max", "max"},
            new String[] {"penetration.mean", "mean"},
            new String[] {"constraintError.max", "max"},
            new String[] {"constraintError.mean", "mean"},
            new String[] {"tunnelling.count", "final"},
            new String[] {"stability.maxSpeed", "max"},
            new String[] {"stability.maxAngularSpeed", "max"},
            new String[] {"stability.nonFinite", "max"},
            new String[] {"sleeping.count", "max"});

    private static final List<String> TRAJECTORY = List.of("x", "y", "angle", "vx", "vy", "omega");

    /** Relative margin inside which the engine and the oracle are equally close to the truth. */
    static final double TIE = 0.05;

    private Comparison() {
    }

    /**
     * One line of the comparison table.
     *
     * @param channel the channel
     * @param figure how the samples reduce: final, max, mean, maxDrift, or series (sample by sample; with a
     *     closed form, followed by how its error reduces: maxError, finalError or rmsError, and its window)
     * @param engine the engine's figure (series: its final value), NaN if the engine did not run
     * @param oracle the oracle's figure (series: its final value), NaN if the oracle did not run
     * @param reference the truth's figure (series: its final value), NaN if there is none
     * @param referenceSource where the truth comes from ({@code closed form pendulum}, {@code law: ...}), or null
     * @param difference engine − oracle (series: the largest |engine − oracle| over the samples)
     * @param tolerance the largest difference that still agrees
     * @param engineError |engine − reference| (series: reduced as the figure says), NaN without reference
     * @param oracleError the same for the oracle
     * @param agreement whether the engine and the oracle agree
     * @param closer which is closer to the truth
     */
    public record Row(String channel, String figure, double engine, double oracle, double reference,
                      String referenceSource, double difference, double tolerance, double engineError,
                      double oracleError, Agreement agreement, Closer closer) {
    }

    /**
     * The comparison of one scene.
     *
     * @param scene the scene id
     * @param file the scene file
     * @param category the scene's category, or null
     * @param status how far it could be compared
     * @param note what the reader should know (why a side is missing, what pymunk leaves out)
     * @param engineStatus the engine run's status (pass, known, FAIL, unsupported, ERROR)
     * @param oracle what the oracle said
     * @param settings the scene's oracle settings
     * @param closedForm the closed-form model's name, or null
     * @param rows the table
     * @param enginePairs the engine's penetration per pair of bodies (its trace's, deepest first), or null
     * @param oraclePairs the oracle's, or null
     */
    public record Scene(String scene, String file, String category, CompareStatus status, String note,
                        String engineStatus, OracleScene oracle, OracleSettings settings, String closedForm,
                        List<Row> rows, List<PenetrationPair> enginePairs, List<PenetrationPair> oraclePairs) {

        /** A scene without penetration per pair (no trace on either side). */
        public Scene(String scene, String file, String category, CompareStatus status, String note,
                     String engineStatus, OracleScene oracle, OracleSettings settings, String closedForm, List<Row> rows) {
            this(scene, file, category, status, note, engineStatus, oracle, settings, closedForm, rows, null, null);
        }
    }

    /**
     * Compares a scene.
     *
     * @param s the scene
     * @param engineStatus the engine run's status
     * @param engine the engine's trace, or null if it did not run
     * @param oracle what the oracle said (null if it was not asked)
     * @param oracleTrace the oracle's trace, or null if it did not run
     * @param closedForm the scene's closed-form model, or null
     */
    public static Scene compare(Scenario s, String engineStatus, Trace engine, OracleScene oracle, Trace oracleTrace,
                                ClosedForm closedForm) {
        return compare(s, engineStatus, engine, oracle, oracleTrace, closedForm, "pymunk");
    }

    /**
     * Compares a scene with one oracle, named in the notes. pymunk has no continuous collision, so in a
     * continuousCollision scene its rows with a reference are judged against the truth only; Box2D has
     * it, so its rows are judged for agreement too.
     *
     * @param oracleName {@code pymunk} or {@code box2d}
     */
    public static Scene compare(Scenario s, String engineStatus, Trace engine, OracleScene oracle, Trace oracleTrace,
                                ClosedForm closedForm, String oracleName) {
        boolean lacksContinuous = oracleName.equals("pymunk");
        OracleSettings settings = OracleSettings.of(s.oracle());
        String model = s.closedForm() != null ? s.closedForm().node().get("model").asText() : null;
        List<String> notes = new ArrayList<>();
        if (engine == null) {
            notes.add("engine: " + engineStatus);
        }
        if (oracleTrace == null) {
            notes.add("oracle: " + (oracle == null ? "not run" : oracle.status()
                    + (oracle.message() != null && !oracle.message().isEmpty() ? " (" + oracle.message() + ")" : "")));
        }
        if (engine != null && oracleTrace != null) {
            String mismatch = mismatch(engine, oracleTrace);
            if (mismatch != null) {
                return new Scene(s.name(), s.file(), s.category(), CompareStatus.ERROR, "the traces do not line up: " + mismatch,
                        engineStatus, oracle, settings, model, List.of());
            }
        }
        boolean incomplete = oracle != null && oracle.incomplete();
        if (oracle != null) {
            // One note per kind, with its count: a world of 14 faced segments says so once.
            Map<String, Integer> kinds = new LinkedHashMap<>();
            for (OracleScene.Note n : oracle.unsupported()) {
                kinds.merge(oracleName + " leaves out " + n.element() + (n.affectsBodies() ? " (changes the motion)" : " (no effect on bodies)"),
                        1, Integer::sum);
            }
            for (OracleScene.Note n : oracle.approximations()) {
                kinds.merge(oracleName + " approximates " + n.element(), 1, Integer::sum);
            }
            kinds.forEach((note, times) -> notes.add(times > 1 ? note + " (x" + times + ")" : note));
        }
        if (settings.continuousCollision() && lacksContinuous) {
            notes.add("tests continuous collision, which pymunk lacks: judged against the reference");
        }
        OracleSettings judged = lacksContinuous ? settings : settings.withoutContinuousCollision();
        Trace any = engine != null ? engine : oracleTrace;
        List<Row> rows = new ArrayList<>();
        if (any != null) {
            int[] samples = window(any, settings);
            Laws laws = new Laws(s, model);
            Set<String> covered = new LinkedHashSet<>();
            // Closed-form rows first: channels the model predicts.
            if (closedForm != null) {
                List<String> candidates = new ArrayList<>();
                for (String b : any.bodies()) {
                    for (String q : TRAJECTORY) {
                        candidates.add(Channels.body(b, q));
                    }
                }
                candidates.addAll(any.metricChannels());
                for (String c : candidates) {
                    if (Double.isNaN(closedForm.predict(c, any.time(samples[0])))) {
                        continue;
                    }
                    rows.add(series(c, engine, oracleTrace, samples, closedForm, "closed form " + model,
                            ErrorFigure.of(s, c, settings), judged, incomplete));
                    covered.add(c);
                }
            }
            for (String[] f : METRIC_FIGURES) {
                if (any.has(f[0]) && !covered.contains(f[0])) {
                    rows.add(aggregate(f[0], f[1], engine, oracleTrace, samples, laws, judged, incomplete));
                }
                // The same figure of the pairs an expectation names (between), after the world's.
                for (String c : any.metricChannels()) {
                    if (Channels.isPair(c) && Channels.base(c).equals(f[0])) {
                        rows.add(aggregate(c, f[1], engine, oracleTrace, samples, laws, judged, incomplete));
                    }
                }
            }
            if (!settings.chaotic()) {
                for (String b : any.bodies()) {
                    BodySpec spec = s.body(b);
                    if (spec == null || spec.state().isStatic()) {
                        continue;
                    }
                    for (String q : TRAJECTORY) {
                        String c = Channels.body(b, q);
                        if (!covered.contains(c)) {
                            rows.add(series(c, engine, oracleTrace, samples, null, null, null, judged, incomplete));
                        }
                    }
                }
            }
        }
        CompareStatus status = engine != null && oracleTrace != null ? CompareStatus.COMPARED
                : oracleTrace != null ? CompareStatus.ORACLE_ONLY : engine != null ? CompareStatus.ENGINE_ONLY
                : CompareStatus.NEITHER;
        if (oracle != null && (oracle.status().equals("error") || oracle.status().equals("invalid"))) {
            status = CompareStatus.ERROR;
        }
        return new Scene(s.name(), s.file(), s.category(), status, String.join("; ", notes), engineStatus, oracle,
                settings, model, rows, engine != null ? engine.penetrationPairs() : null,
                oracleTrace != null ? oracleTrace.penetrationPairs() : null);
    }

    /** Why two traces of the same scene cannot be compared sample by sample, or null. */
    static String mismatch(Trace a, Trace b) {
        if (a.size() != b.size()) {
            return a.size() + " samples against " + b.size();
        }
        for (int i = 0; i < a.size(); i++) {
            if (a.tick(i) != b.tick(i)) {
                return "sample " + i + " is tick " + a.tick(i) + " against " + b.tick(i);
            }
        }
        if (!new LinkedHashSet<>(a.bodies()).equals(new LinkedHashSet<>(b.bodies()))) {
            return "bodies " + a.bodies() + " against " + b.bodies();
        }
        if (!new LinkedHashSet<>(a.metricChannels()).equals(new LinkedHashSet<>(b.metricChannels()))) {
            return "metrics " + a.metricChannels() + " against " + b.metricChannels();
        }
        return null;
    }

    private static int[] window(Trace t, OracleSettings settings) {
        List<Integer> in = new ArrayList<>();
        for (int i = 0; i < t.size(); i++) {
            if (settings.inWindow(t.time(i))) {
                in.add(i);
            }
        }
        if (in.isEmpty()) {
            in.add(t.size() - 1);
        }
        return in.stream().mapToInt(Integer::intValue).toArray();
    }

    private static Row aggregate(String channel, String figure, Trace engine, Trace oracle, int[] samples, Laws laws,
                                 OracleSettings settings, boolean incomplete) {
        double[] e = engine != null ? engine.column(channel) : null;
        double[] o = oracle != null ? oracle.column(channel) : null;
        double fe = e != null ? reduce(e, samples, figure) : Double.NaN;
        double fo = o != null ? reduce(o, samples, figure) : Double.NaN;
        String law = laws.of(channel);
        double ref = law != null ? 0 : Double.NaN;
        double scale = Math.max(scale(e, samples), scale(o, samples));
        double tol = tolerance(settings, channel, scale);
        double errE = law != null ? Math.abs(fe - ref) : Double.NaN;
        double errO = law != null ? Math.abs(fo - ref) : Double.NaN;
        return row(channel, figure, fe, fo, ref, law, fe - fo, tol, errE, errO, scale, e != null && o != null, settings,
                incomplete);
    }

    private static Row series(String channel, Trace engine, Trace oracle, int[] samples, ClosedForm truth, String source,
                              ErrorFigure errorFigure, OracleSettings settings, boolean incomplete) {
        double[] e = engine != null ? engine.column(channel) : null;
        double[] o = oracle != null ? oracle.column(channel) : null;
        Trace any = engine != null ? engine : oracle;
        int last = samples[samples.length - 1];
        double diff = e != null && o != null ? 0 : Double.NaN;
        for (int i : samples) {
            if (e != null && o != null) {
                diff = Math.max(diff, absOrInf(e[i] - o[i]));
            }
        }
        double errE = Double.NaN;
        double errO = Double.NaN;
        double ref = Double.NaN;
        String figure = "series";
        if (truth != null) {
            int[] at = errorFigure.samples(any);
            errE = e != null ? errorFigure.error(e, at, any, truth, channel) : Double.NaN;
            errO = o != null ? errorFigure.error(o, at, any, truth, channel) : Double.NaN;
            ref = truth.predict(channel, any.time(last));
            figure = "series, " + errorFigure.label();
        }
        double scale = Math.max(scale(e, samples), scale(o, samples));
        double tol = tolerance(settings, channel, scale);
        return row(channel, figure, e != null ? e[last] : Double.NaN, o != null ? o[last] : Double.NaN, ref, source,
                diff, tol, errE, errO, scale, e != null && o != null, settings, incomplete);
    }

    /**
     * How a series' error against the closed form reduces to one figure: as the scene's own closedForm
     * expectation on that channel does (maxError, finalError or rmsError, in its window), or the largest
     * error over the comparison window when the scene has none.
     */
    record ErrorFigure(String of, double from, double until) {
        static ErrorFigure of(Scenario s, String channel, OracleSettings settings) {
            for (ExpectationSpec e : s.run().expect()) {
                if (e.kind() == ExpectationSpec.Kind.CLOSED_FORM && channel.equals(e.channel()) && e.of() != null) {
                    return new ErrorFigure(e.of(), e.windowFrom(), e.windowUntil());
                }
            }
            return new ErrorFigure("maxError", settings.windowFrom(), settings.windowUntil());
        }

        String label() {
            if (from <= 0 && Double.isInfinite(until)) {
                return of;
            }
            return of + " in [" + CompareReport.fmt(from) + ", " + CompareReport.fmt(until) + "] s";
        }

        int[] samples(Trace t) {
            List<Integer> in = new ArrayList<>();
            for (int i = 0; i < t.size(); i++) {
                double time = t.time(i);
                if (time >= from - 1e-9 && time <= until + 1e-9) {
                    in.add(i);
                }
            }
            return in.stream().mapToInt(Integer::intValue).toArray();
        }

        double error(double[] v, int[] at, Trace t, ClosedForm truth, String channel) {
            double max = 0;
            double squares = 0;
            double last = Double.NaN;
            int n = 0;
            for (int i : at) {
                double p = truth.predict(channel, t.time(i));
                if (Double.isNaN(p)) {
                    continue;
                }
                double err = absOrInf(v[i] - p);
                max = Math.max(max, err);
                squares += err * err;
                last = err;
                n++;
            }
            if (n == 0) {
                return Double.NaN;
            }
            return switch (of) {
                case "finalError" -> last;
                case "rmsError" -> Math.sqrt(squares / n);
                default -> max;
            };
        }
    }

    private static Row row(String channel, String figure, double engine, double oracle, double ref, String source,
                           double difference, double tol, double errE, double errO, double scale, boolean both,
                           OracleSettings settings, boolean incomplete) {
        Agreement agreement;
        if (!both) {
            agreement = Agreement.NONE;
        } else if (incomplete || (settings.continuousCollision() && source != null)) {
            agreement = Agreement.NOT_JUDGED;
        } else {
            agreement = Math.abs(difference) <= tol ? Agreement.AGREE : Agreement.DIFFER;  // NaN differs
        }
        Closer closer = Closer.NONE;
        if (source != null && both && !incomplete) {
            closer = closer(errE, errO, scale);
        }
        return new Row(channel, figure, engine, oracle, ref, source, difference, tol, errE, errO, agreement, closer);
    }

    /** Which of two errors is smaller, or a tie when they are within float noise or 5% of each other. */
    static Closer closer(double errE, double errO, double scale) {
        double e = Double.isNaN(errE) ? Double.POSITIVE_INFINITY : errE;
        double o = Double.isNaN(errO) ? Double.POSITIVE_INFINITY : errO;
        if (e == o) {
            return Closer.TIE;
        }
        double noise = 1e-6 * (Double.isFinite(scale) ? scale : 0) + 1e-9;
        if (Double.isFinite(e) && Double.isFinite(o)
                && (Math.max(e, o) <= noise || Math.abs(e - o) <= Math.max(noise, TIE * Math.max(e, o)))) {
            return Closer.TIE;
        }
        return e < o ? Closer.ENGINE : Closer.ORACLE;
    }

    /**
     * The tolerance on the engine–oracle difference of a channel when the scene states none (scale: the
     * largest |value| of the channel in either trace). Documented in scenarios/README.md.
     */
    public static double defaultTolerance(String pairOrChannel, double scale) {
        String channel = Channels.base(pairOrChannel);
        String[] bc = Channels.bodyChannel(channel);
        if (bc != null) {
            return switch (bc[1]) {
                case "x", "y" -> 1;
                case "angle" -> 0.05;
                case "omega" -> Math.max(0.1, 0.05 * scale);
                default -> Math.max(1, 0.05 * scale);
            };
        }
        return switch (channel) {
            case "momentum.x", "momentum.y" -> Math.max(0.01, 0.02 * scale);
            case "energy.total", "energy.kinetic", "energy.potential", "angularMomentum" -> Math.max(1, 0.02 * scale);
            case "penetration.max", "penetration.mean", "constraintError.max", "constraintError.mean" -> 0.25;
            case "stability.maxSpeed" -> Math.max(1, 0.05 * scale);
            case "stability.maxAngularSpeed" -> Math.max(0.1, 0.05 * scale);
            default -> 0;
        };
    }

    private static double tolerance(OracleSettings settings, String channel, double scale) {
        double t = settings.tolerance(channel);
        return Double.isNaN(t) ? defaultTolerance(channel, Double.isFinite(scale) ? scale : 0) : t;
    }

    static double reduce(double[] v, int[] samples, String figure) {
        double first = v[samples[0]];
        double out = switch (figure) {
            case "max", "maxDrift" -> Double.NEGATIVE_INFINITY;
            default -> 0;
        };
        for (int i : samples) {
            double x = v[i];
            if (Double.isNaN(x)) {
                return Double.NaN;
            }
            switch (figure) {
                case "max" -> out = Math.max(out, x);
                case "maxDrift" -> out = Math.max(out, Math.abs(x - first));
                case "mean" -> out += x / samples.length;
                default -> out = x;
            }
        }
        return out;
    }

    private static double scale(double[] v, int[] samples) {
        if (v == null) {
            return 0;
        }
        double s = 0;
        for (int i : samples) {
            if (Double.isFinite(v[i])) {
                s = Math.max(s, Math.abs(v[i]));
            }
        }
        return s;
    }

    private static double absOrInf(double d) {
        return Double.isNaN(d) ? Double.POSITIVE_INFINITY : Math.abs(d);
    }

    /** The laws that give a metric channel's true figure in a scene (the figure is 0 for each). */
    static final class Laws {
        private final boolean isolated;
        private final boolean conservative;
        // A one-sided landscape segment lets bodies through from its open side on purpose.
        private final boolean oneSided;

        Laws(Scenario s, String model) {
            boolean gravity = s.world().gravityX() != 0 || s.world().gravityY() != 0;
            boolean pushed = false;
            for (ActionSpec a : s.actions()) {
                // A particle burst acts on no body.
                if (a.kind() != ActionSpec.Kind.emit
                        && (a.kind() != ActionSpec.Kind.gravity || a.vector()[0] != 0 || a.vector()[1] != 0)) {
                    pushed = true;
                }
            }
            boolean anyStatic = s.bodies().stream().anyMatch(b -> b.state().isStatic());
            boolean damped = s.world().dampingLateral() != 0 || s.world().dampingRotational() != 0;
            boolean external = s.elements().containsKey("landscape") || s.elements().containsKey("motors")
                    || s.elements().containsKey("world.simulationArea");
            isolated = !gravity && !pushed && !anyStatic && !damped && !external;
            conservative = model != null && List.of("projectile", "freeRotation", "pendulum").contains(model)
                    && !damped && !pushed;
            oneSided = hasOneSidedSegment(s);
        }

        private static boolean hasOneSidedSegment(Scenario s) {
            Section landscape = s.elements().get("landscape");
            if (landscape == null) {
                return false;
            }
            for (JsonNode segment : landscape.node().path("segments")) {
                String face = segment.path("face").asText("none");
                if (!face.equals("none")) {
                    return true;
                }
            }
            return false;
        }

        /** The law for a channel's figure, or null. */
        String of(String channel) {
            return switch (Channels.base(channel)) {
                case "penetration.max", "penetration.mean" -> "law: rigid bodies do not overlap";
                case "tunnelling.count" -> oneSided ? null : "law: no body passes through a wall";
                case "constraintError.max", "constraintError.mean" -> "law: joints hold exactly";
                case "stability.nonFinite" -> "law: the state stays finite";
                case "momentum.x", "momentum.y", "angularMomentum" ->
                        isolated ? "law: an isolated system keeps its momentum" : null;
                case "energy.total" -> conservative ? "law: no contact or friction, energy is kept" : null;
                default -> null;
            };
        }
    }
}
