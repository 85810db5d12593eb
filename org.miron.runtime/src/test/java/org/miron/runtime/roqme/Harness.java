package org.miron.runtime.roqme;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.miron.runtime.roqme.expr.CompiledModel;

/**
 * A runtime model around the patterns under test, written as JSON like the generator writes it
 * (types left out: the compiler infers them), driven input by input. Contexts: x, y (number),
 * b (boolean), e, f (eventtype), mode (enum LOW MEDIUM HIGH), arr (3 numbers), d := x * 2;
 * param P (number, default 30); property p.
 */
final class Harness {
    final List<String> observations = new ArrayList<>();
    final List<String> timers = new ArrayList<>();
    final List<String> vars = new ArrayList<>();
    final List<String> beliefs = new ArrayList<>();
    Provider provider;
    CompiledModel model;
    private final List<String> fired = new ArrayList<>();

    static String ref(String id) {
        return "{\"ref\":\"" + id + "\"}";
    }

    static String num(double v) {
        return "{\"number\":" + v + "}";
    }

    static String bool(boolean v) {
        return "{\"boolean\":" + v + "}";
    }

    static String time(long ms) {
        return "{\"time\":" + ms + "}";
    }

    static String enumLit(String lit) {
        return "{\"enum\":\"" + lit + "\",\"enumType\":\"Mode\"}";
    }

    static String bin(String op, String l, String r) {
        return "{\"op\":\"" + op + "\",\"left\":" + l + ",\"right\":" + r + "}";
    }

    static String un(String op, String a) {
        return "{\"op\":\"" + op + "\",\"arg\":" + a + "}";
    }

    static String call(String fn, String... args) {
        return "{\"call\":\"" + fn + "\",\"args\":[" + String.join(",", args) + "]}";
    }

    static String decl(String id) {
        return "\"id\":\"" + id + "\",\"name\":\"" + id + "\",\"namespace\":\"T\",\"at\":\"t.roqme:1:" + id.length() + "\"";
    }

    Harness obs(String id, String pattern, String... actions) {
        String acts = actions.length == 0 ? "{\"kind\":\"reinforces\",\"belief\":\"p\",\"strength\":\"MEDIUM\",\"survivalMs\":null}"
                : String.join(",", actions);
        observations.add("{" + decl(id) + ",\"pattern\":" + pattern + ",\"actions\":[" + acts + "]}");
        return this;
    }

    Harness timer(String id, Long periodMs, String schedule, long offsetMs, boolean onetime, boolean paused) {
        timers.add("{" + decl(id) + ",\"periodMs\":" + periodMs + ",\"schedule\":" + (schedule == null ? "null" : "\"" + schedule + "\"")
                + ",\"offsetMs\":" + offsetMs + ",\"onetime\":" + onetime + ",\"paused\":" + paused + "}");
        return this;
    }

    Harness var(String id, String init) {
        vars.add("{" + decl(id) + ",\"type\":{\"kind\":\"number\"}" + (init == null ? "" : ",\"init\":" + init) + "}");
        return this;
    }

    Harness belief(String json) {
        beliefs.add(json);
        return this;
    }

    String json() {
        String contexts = String.join(",",
                "{" + decl("x") + ",\"type\":{\"kind\":\"number\"}}",
                "{" + decl("y") + ",\"type\":{\"kind\":\"number\"}}",
                "{" + decl("b") + ",\"type\":{\"kind\":\"boolean\"}}",
                "{" + decl("e") + ",\"type\":{\"kind\":\"eventtype\"}}",
                "{" + decl("f") + ",\"type\":{\"kind\":\"eventtype\"}}",
                "{" + decl("mode") + ",\"type\":{\"kind\":\"enum\",\"literals\":[\"LOW\",\"MEDIUM\",\"HIGH\"]}}",
                "{" + decl("arr") + ",\"type\":{\"kind\":\"number\",\"cardinality\":3}}",
                "{" + decl("d") + ",\"type\":{\"kind\":\"number\"},\"derived\":" + bin("*", ref("x"), num(2)) + "}");
        List<String> bs = new ArrayList<>(beliefs);
        bs.add(0, "{" + decl("p") + ",\"kind\":\"property\",\"reference\":0.5,\"survivalMs\":null,\"expr\":null}");
        return "{\"format\":1,\"model\":\"t\",\"source\":\"t.roqme\",\"contexts\":[" + contexts + "],"
                + "\"params\":[{" + decl("P") + ",\"type\":{\"kind\":\"number\"},\"default\":{\"number\":30}}],"
                + "\"vars\":[" + String.join(",", vars) + "],\"timers\":[" + String.join(",", timers) + "],"
                + "\"beliefs\":[" + String.join(",", bs) + "],\"observations\":[" + String.join(",", observations) + "]}";
    }

    Harness start() throws Exception {
        return start(Map.of(), 1000);
    }

    Harness start(Map<String, String> params, long period) throws Exception {
        model = RoqmeFixtures.compile(json(), new HashMap<>(params));
        provider = new Provider(model, period, 0).onFire((o, t) -> fired.add(o.id())).start();
        fired.clear();
        return this;
    }

    /** Feeds one sample at time t; returns the observations fired by it (and by what was due before). */
    List<String> in(String ctx, Object value, long t) {
        fired.clear();
        Object v = value instanceof Integer i ? (Object) i.doubleValue() : value;
        provider.input(model.symbols().get(ctx).slot(), v, t);
        return new ArrayList<>(fired);
    }

    /** Runs what is due up to t; returns what fired. */
    List<String> until(long t) {
        fired.clear();
        provider.advanceTo(t);
        return new ArrayList<>(fired);
    }

    Object value(String id) {
        return provider.value(id);
    }
}
