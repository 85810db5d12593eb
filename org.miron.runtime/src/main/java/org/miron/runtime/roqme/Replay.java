package org.miron.runtime.roqme;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.Writer;
import java.util.List;
import org.miron.runtime.Json;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * The provider on a virtual clock, driven by a JSON Lines trace of {@code roqme.context} bodies with
 * their {@code time} in ms. The clock starts at {@code start} (default: the first record's time);
 * tick k covers (start + (k-1)·period, start + k·period]; by default it runs through the tick
 * holding the last record. A record before the start is applied at the start. Output: CSV
 * {@code tick,time,<properties>,fired} (time in ms since start) or JSON Lines.
 */
public final class Replay {
    /** A trace line that cannot be replayed: the message names the line. */
    public static final class TraceException extends Exception {
        private static final long serialVersionUID = 1L;

        TraceException(String message) {
            super(message);
        }
    }

    public enum Format { CSV, JSONL }

    private final CompiledModel model;
    private final long periodMs;
    private final Long start;
    private final Long ticks;
    private final Format format;

    /** {@code start}, {@code ticks}: null for their defaults. */
    public Replay(CompiledModel model, long periodMs, Long start, Long ticks, Format format) {
        this.model = model;
        this.periodMs = periodMs;
        this.start = start;
        this.ticks = ticks;
        this.format = format;
    }

    /** Replays {@code trace} (named {@code traceName} in messages) and writes the ticks; returns their number. */
    public long run(BufferedReader trace, String traceName, Writer out) throws IOException, TraceException {
        ContextDecoder decoder = new ContextDecoder(model);
        List<String> props = model.beliefs().stream().filter(b -> b.decl().isProperty()).map(b -> b.decl().name()).toList();
        if (format == Format.CSV) {
            out.write("tick,time," + String.join(",", props) + ",fired\n");
        }
        Provider p = null;
        long lastTime = Long.MIN_VALUE;
        long lineNo = 0;
        long written = 0;
        String line;
        while ((line = trace.readLine()) != null) {
            lineNo++;
            if (line.isBlank()) {
                continue;
            }
            ContextDecoder.Sample s;
            try {
                s = decoder.decode(line);
            } catch (ContextDecoder.BadContext e) {
                throw new TraceException(traceName + ":" + lineNo + ": error [trace]: " + e.getMessage());
            }
            if (s == null) {
                continue; // a derived context the provider published: recorded with the inputs, not one
            }
            if (s.time() == null) {
                throw new TraceException(traceName + ":" + lineNo + ": error [trace]: the record has no time (ms)");
            }
            long t = s.time();
            if (t < lastTime) {
                throw new TraceException(traceName + ":" + lineNo + ": error [trace]: time " + t
                        + " is before the previous record's " + lastTime);
            }
            lastTime = t;
            if (p == null) {
                p = new Provider(model, periodMs, start != null ? start : t).start();
            }
            // ticks that end before this record are complete
            while (p.nextTickTime() < t && (ticks == null || p.nextTick() <= ticks)) {
                write(p.tick(), p.startMs(), props, out);
                written++;
            }
            if (ticks != null && p.nextTick() > ticks) {
                break;
            }
            p.input(s.slot(), s.value(), Math.max(t, p.startMs()));
        }
        if (p == null) {
            p = new Provider(model, periodMs, start != null ? start : 0).start();
        }
        long last = ticks != null ? ticks
                : Math.max(1, lastTime == Long.MIN_VALUE ? 1 : ceilDiv(lastTime - p.startMs(), periodMs));
        while (p.nextTick() <= last) {
            write(p.tick(), p.startMs(), props, out);
            written++;
        }
        out.flush();
        return written;
    }

    private static long ceilDiv(long a, long b) {
        return a <= 0 ? 1 : -Math.floorDiv(-a, b);
    }

    private void write(Provider.Tick t, long startMs, List<String> props, Writer out) throws IOException {
        double time = (double) (t.timeMs() - startMs);
        if (format == Format.CSV) {
            StringBuilder b = new StringBuilder();
            b.append(t.k()).append(',').append(plain(time));
            for (double e : t.estimates()) {
                b.append(',').append(e);
            }
            b.append(',').append(String.join(":", t.fired())).append('\n');
            out.write(b.toString());
        } else {
            ObjectNode o = Json.object();
            o.put("tick", t.k());
            o.put("time", time);
            ObjectNode est = o.putObject("estimates");
            for (int i = 0; i < props.size(); i++) {
                est.put(props.get(i), t.estimates()[i]);
            }
            var fired = o.putArray("fired");
            t.fired().forEach(fired::add);
            out.write(Json.write(o));
            out.write('\n');
        }
    }

    /** A double without exponent ({@code 86400000.0}, not {@code 8.64E7}), every digit kept. */
    static String plain(double v) {
        String p = java.math.BigDecimal.valueOf(v).toPlainString();
        return p.indexOf('.') < 0 ? p + ".0" : p;
    }

    /** The property names of a model in declaration order (the CSV's columns). */
    public static List<String> properties(RoqmeModel m) {
        return m.beliefs().stream().filter(RoqmeModel.Belief::isProperty).map(RoqmeModel.Belief::name).toList();
    }
}
