package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.scenario.MetricSpec;
import org.emini.particle.ParticleEmitter;

/**
 * particles.count = the live particles of the watched emitters ({@code emitters}, default all);
 * particles.outside = how many of them lie outside {@code region} (strictly: a particle on its edge is
 * inside), 0 without a region. Particles never act on bodies, so these are the only figures about them.
 */
final class ParticlesMetric implements Metric {
    private final ParticleEmitter[] emitters;
    private final double[] min;
    private final double[] max;

    ParticlesMetric(BuiltWorld built, MetricSpec spec) {
        List<ParticleEmitter> list = new ArrayList<>();
        if (spec.emitters().isEmpty()) {
            list.addAll(built.emitters().values());
        } else {
            for (String name : spec.emitters()) {
                list.add(built.emitters().get(name));
            }
        }
        emitters = list.toArray(new ParticleEmitter[0]);
        min = spec.regionMin();
        max = spec.regionMax();
    }

    @Override
    public List<String> channels() {
        return List.of("particles.count", "particles.outside");
    }

    @Override
    public void sample(double[] out, int offset) {
        int count = 0;
        int outside = 0;
        for (ParticleEmitter e : emitters) {
            int n = e.getParticleCount();
            count += n;
            if (min != null) {
                for (int i = 0; i < n; i++) {
                    double x = e.getX(i);
                    double y = e.getY(i);
                    if (!(x >= min[0] && x <= max[0] && y >= min[1] && y <= max[1])) {
                        outside++;
                    }
                }
            }
        }
        out[offset] = count;
        out[offset + 1] = outside;
    }
}
