package org.miron.runtime.engine;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.EngineFixture;

/** What the engine takes from the bus, and what it refuses (docs/wire-formats.md). */
public class InputDecoderTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    /**
     * The robot's contexts are published for the RoQME provider: the engine reads the ones its
     * rules name (testbot: BatteryLevel, Space) and passes over the rest without a complaint.
     */
    @Test
    public void aContextTheRulesDoNotReadIsPassedOver() throws Exception {
        IoModel model = IoModel.load(new EngineFixture(tmp.getRoot().toPath()).ioJson);
        InputState state = new InputState(model);
        InputDecoder decoder = new InputDecoder(model, state);
        long before = state.version();
        decoder.apply(Topics.CONTEXT, body("{\"name\":\"HumanDistance\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":0.4}"));
        decoder.apply(Topics.CONTEXT, body("{\"name\":\"Docked\",\"type\":\"boolean\",\"value\":true}"));
        assertEquals("nothing changed", before, state.version());

        decoder.apply(Topics.CONTEXT, body("{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":4}"));
        assertEquals(4.0, state.snapshot().params().get("context_Intralogistics_BatteryLevel"));
        // a context the rules read still has to be right, and every message needs a name
        refused(decoder, "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":true}",
                BadInputException.Kind.TYPE);
        refused(decoder, "{\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":1}", BadInputException.Kind.MALFORMED);
        // estimates are the engine's own inputs: an unknown metric is refused
        try {
            decoder.apply(Topics.ESTIMATE, body("{\"name\":\"comfort\",\"namespace\":\"Intralogistics\",\"value\":0.1}"));
            fail("an unknown metric was taken");
        } catch (BadInputException e) {
            assertEquals(BadInputException.Kind.UNKNOWN, e.kind());
        }
    }

    private static void refused(InputDecoder decoder, String json, BadInputException.Kind kind) {
        try {
            decoder.apply(Topics.CONTEXT, body(json));
            fail("taken: " + json);
        } catch (BadInputException e) {
            assertEquals(json, kind, e.kind());
        }
    }

    private static byte[] body(String json) {
        return json.getBytes(UTF_8);
    }
}
