package org.miron.runtime.sim;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.miron.runtime.sim.WorldModel.Measure;

/**
 * The running values of a world's measures over one run: integrals and time fractions with the
 * state held between two instants, counts of events and of a condition becoming true, the final
 * value at the end; and the time-average of every RoQME metric estimate.
 */
final class Measures {
    private final List<Measure> measures;
    private final double[] acc;
    private final boolean[] was;
    private final String[] metricNames;
    private final double[] metricAcc;
    private final double[] metricNow;

    Measures(List<Measure> measures, List<String> metrics, double[] initialEstimates) {
        this.measures = measures;
        this.acc = new double[measures.size()];
        this.was = new boolean[measures.size()];
        this.metricNames = metrics.toArray(new String[0]);
        this.metricAcc = new double[metricNames.length];
        this.metricNow = initialEstimates.clone();
    }

    /** The state of {@code world} held for {@code seconds} (evaluated before the world advances). */
    void hold(World world, double seconds) {
        if (seconds <= 0) {
            return;
        }
        for (int i = 0; i < acc.length; i++) {
            Measure m = measures.get(i);
            switch (m.kind()) {
                case INTEGRAL, MEAN -> acc[i] += world.number(m.expr()) * seconds;
                case FRACTION -> acc[i] += world.bool(m.expr()) ? seconds : 0;
                default -> {
                }
            }
        }
        for (int i = 0; i < metricAcc.length; i++) {
            metricAcc[i] += metricNow[i] * seconds;
        }
    }

    /** After an instant: its events, and conditions that became true. */
    void instant(World world, List<String> events) {
        for (int i = 0; i < acc.length; i++) {
            Measure m = measures.get(i);
            if (m.kind() != Measure.Kind.COUNT) {
                continue;
            }
            if (m.event() != null) {
                for (String e : events) {
                    if (e.equals(m.event())) {
                        acc[i]++;
                    }
                }
            } else {
                boolean now = world.bool(m.expr());
                if (now && !was[i]) {
                    acc[i]++;
                }
                was[i] = now;
            }
        }
    }

    void estimates(double[] values) {
        System.arraycopy(values, 0, metricNow, 0, Math.min(values.length, metricNow.length));
    }

    /** Every measure by name, then {@code metric:<property>} for the metrics' time-averages. */
    Map<String, Double> finish(World world, double seconds) {
        Map<String, Double> out = new LinkedHashMap<>();
        for (int i = 0; i < acc.length; i++) {
            Measure m = measures.get(i);
            double v = switch (m.kind()) {
                case FRACTION, MEAN -> seconds > 0 ? acc[i] / seconds : 0;
                case FINAL -> world.number(m.expr());
                default -> acc[i];
            };
            out.put(m.name(), v);
        }
        for (int i = 0; i < metricAcc.length; i++) {
            out.put("metric:" + metricNames[i], seconds > 0 ? metricAcc[i] / seconds : metricNow[i]);
        }
        return out;
    }
}
