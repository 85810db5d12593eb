package org.miron.runtime.roqme;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.HashMap;
import java.util.Map;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.testkit.runtime.TestModels;

/** Loads the hand-written runtime models (the test kit's TestModels.roqme) and replays traces in memory. */
final class RoqmeFixtures {
    private RoqmeFixtures() {
    }

    static String resource(String name) throws IOException {
        return TestModels.roqme(name);
    }

    static CompiledModel compile(String json) throws ModelException {
        return Compiler.compile(ModelReader.parse("test.roqme.json", json), new HashMap<>());
    }

    static CompiledModel compile(String json, Map<String, String> params) throws ModelException {
        return Compiler.compile(ModelReader.parse("test.roqme.json", json), new HashMap<>(params));
    }

    static String replay(CompiledModel m, String trace, long period, Long ticks) throws Exception {
        StringWriter out = new StringWriter();
        new Replay(m, period, null, ticks, Replay.Format.CSV).run(new BufferedReader(new StringReader(trace)), "trace", out);
        return out.toString();
    }
}
