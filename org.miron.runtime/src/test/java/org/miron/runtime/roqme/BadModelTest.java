package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;
import static org.miron.runtime.roqme.Harness.bin;
import static org.miron.runtime.roqme.Harness.num;
import static org.miron.runtime.roqme.Harness.ref;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.Test;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;

/** A model the provider cannot run is refused at start with the declaration's file:line:col and the reason. */
public class BadModelTest {
    @org.junit.Rule
    public org.junit.rules.TemporaryFolder tmp = new org.junit.rules.TemporaryFolder();

    private static String refused(Harness h, Map<String, String> params) {
        try {
            RoqmeFixtures.compile(h.json(), params);
        } catch (ModelException e) {
            return e.getMessage();
        }
        fail("accepted");
        return null;
    }

    private static String refused(Harness h) {
        return refused(h, Map.of());
    }

    @Test
    public void unknownReferenceNamesTheObservation() {
        assertEquals("t.roqme:1:8: error [roqme-ref]: unknown name nope",
                refused(new Harness().obs("tooClose", bin("<", ref("nope"), num(1)))));
    }

    @Test
    public void unknownBeliefInAnAction() {
        assertEquals("t.roqme:1:1: error [roqme-ref]: unknown belief ghost", refused(new Harness().obs("o", ref("e"),
                "{\"kind\":\"reinforces\",\"belief\":\"ghost\",\"strength\":\"HIGH\",\"survivalMs\":null}")));
    }

    @Test
    public void unknownStrengthAndAction() {
        assertEquals("t.roqme:1:1: error [roqme-action]: o: unknown strength HUGE", refused(new Harness().obs("o", ref("e"),
                "{\"kind\":\"reinforces\",\"belief\":\"p\",\"strength\":\"HUGE\",\"survivalMs\":null}")));
        assertEquals("t.roqme:1:1: error [roqme-action]: o: unsupported action kind 'boosts'",
                refused(new Harness().obs("o", ref("e"), "{\"kind\":\"boosts\",\"belief\":\"p\"}")));
    }

    @Test
    public void cycleBetweenVars() {
        String m = refused(new Harness().var("va", bin("+", ref("vb"), num(1))).var("vb", bin("+", ref("va"), num(1))));
        assertEquals(true, m.matches("t\\.roqme:1:2: error \\[roqme-cycle\\]: .*"));
    }

    @Test
    public void badTimers() {
        assertEquals("t.roqme:1:1: error [roqme-cron]: timer t: bad day of week value 'L'",
                refused(new Harness().timer("t", null, "* * * * L", 0, false, false)));
        assertEquals("t.roqme:1:1: error [roqme-timer]: timer t needs exactly one of periodMs and schedule",
                refused(new Harness().timer("t", 1000L, "* * * * *", 0, false, false)));
    }

    @Test
    public void eventOperatorAsAValue() {
        assertEquals("t.roqme:1:1: error [roqme-expr]: the pattern operator 'and' cannot be used as a value",
                refused(new Harness().obs("o", "{\"op\":\"while\",\"arg\":" + ref("e") + ",\"cond\":" + bin("and", ref("e"), ref("f")) + "}")));
    }

    @Test
    public void badParams() {
        assertEquals("t.roqme:1:1: error [roqme-param]: --param P=high is not a number",
                refused(new Harness(), Map.of("P", "high")));
        assertEquals("t.roqme: error [roqme-param]: --param Q: the model declares no such param",
                refused(new Harness(), Map.of("Q", "1")));
    }

    @Test
    public void unreadableFiles() throws Exception {
        Path dir = tmp.getRoot().toPath();
        Path f = dir.resolve("m.roqme.json");
        Files.writeString(f, "{\"format\":1,\n \"contexts\": [}");
        try {
            ModelReader.read(f);
            fail();
        } catch (ModelException e) {
            assertEquals(true, e.getMessage().startsWith(f + ":2:15: error [roqme-json]: "));
        }
        Files.writeString(f, "{\"format\":2}");
        try {
            ModelReader.read(f);
            fail();
        } catch (ModelException e) {
            assertEquals(f + ": error [roqme-format]: unsupported format 2 (this provider reads format 1)", e.getMessage());
        }
        try {
            ModelReader.read(dir.resolve("none.roqme.json"));
            fail();
        } catch (ModelException e) {
            assertEquals(dir.resolve("none.roqme.json") + ": error [roqme-io]: no such file", e.getMessage());
        }
    }
}
