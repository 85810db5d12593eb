package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Json;
import org.miron.testkit.runtime.TestModels;

/** {@code miron roqme replay} in process on real files; {@code roqme run}'s refusals. */
public class RoqmeCommandTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private Path dir;

    @Before
    public void setUp() throws IOException {
        dir = tmp.getRoot().toPath();
        for (String f : List.of("worked.roqme.json", "worked.trace.jsonl", "intralogistics.roqme.json")) {
            TestModels.copyRoqme(f, dir);
        }
    }

    private String p(String f) {
        return dir.resolve(f).toString();
    }

    @Test
    public void replayPrintsTheWorkedExample() {
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 0, cli.run("roqme", "replay", p("worked.roqme.json"), "--trace", p("worked.trace.jsonl")));
        String[] lines = cli.out().split("\n");
        assertEquals("tick,time,safety,autonomy,fired", lines[0]);
        assertEquals("by default through the tick holding the last record (t = 5999 ms: tick 6)", 7, lines.length);
        assertEquals("6,6000.0,", lines[6].substring(0, 9));
        assertEquals("1,1000.0,0.3333333333333333,0.8,near", lines[1]);
        String[] t6 = lines[6].split(",");
        assertEquals("6", t6[0]);
        assertEquals("low", t6[4]);
        assertEquals(0.483393, Double.parseDouble(t6[2]), 1e-6);
        assertEquals(0.145455, Double.parseDouble(t6[3]), 1e-6);
    }

    @Test
    public void replayTimesHaveNoExponent() throws Exception {
        Path trace = dir.resolve("late.jsonl");
        Files.writeString(trace, "{\"name\":\"Near\",\"value\":true,\"time\":0}\n{\"name\":\"Low\",\"value\":true,\"time\":86400000}\n");
        Cli cli = new Cli();
        assertEquals(0, cli.run("roqme", "replay", p("worked.roqme.json"), "--trace", trace.toString(), "--period", "60000"));
        String[] lines = cli.out().split("\n");
        assertEquals(1 + 1440, lines.length); // 24 h of minutes
        assertTrue(lines[1440], lines[1440].startsWith("1440,86400000.0,"));
        assertTrue(lines[1440], lines[1440].endsWith(",low"));
    }

    @Test
    public void replayAsJsonLinesWithOptions() throws Exception {
        Path out = dir.resolve("out.jsonl");
        assertEquals(0, Cli.exit("roqme", "replay", p("worked.roqme.json"), "--trace", p("worked.trace.jsonl"),
                "--format", "jsonl", "--ticks", "3", "--period", "2000", "--start", "999000", "-o", out.toString()));
        List<String> lines = Files.readAllLines(out);
        assertEquals(3, lines.size());
        JsonNode first = Json.MAPPER.readTree(lines.get(0));
        assertEquals(1, first.path("tick").asInt());
        assertEquals(2000.0, first.path("time").asDouble(), 0);
        // the clock starts at 999000: tick 1 (999000, 1001000] holds the first near only
        assertEquals("[\"near\"]", first.path("fired").toString());
        assertEquals(1 / 3.0, first.path("estimates").path("safety").asDouble(), 1e-12);
        assertEquals(0.8, first.path("estimates").path("autonomy").asDouble(), 1e-12);
        assertEquals("[\"near\"]", Json.MAPPER.readTree(lines.get(1)).path("fired").toString());
    }

    @Test
    public void replayParamOverridesTheDefault() throws Exception {
        Path trace = dir.resolve("battery.jsonl");
        Files.writeString(trace, "{\"name\":\"BatteryLevel\",\"type\":\"number\",\"value\":25,\"time\":0}\n"
                + "{\"name\":\"BatteryLevel\",\"type\":\"number\",\"value\":24,\"time\":1500}\n");
        Cli def = new Cli();
        assertEquals(0, def.run("roqme", "replay", p("intralogistics.roqme.json"), "--trace", trace.toString()));
        assertEquals("tick,time,safety,mission_completion,power_autonomy,fired", def.out().split("\n")[0]);
        assertTrue(def.out(), def.out().split("\n")[1].endsWith(",batteryLow")); // 25 < 30
        Cli low = new Cli();
        assertEquals(0, low.run("roqme", "replay", p("intralogistics.roqme.json"), "--trace", trace.toString(), "--param", "LowBattery=20"));
        assertEquals("1,1000.0,0.7,0.5,0.5,", low.out().split("\n")[1]);
    }

    @Test
    public void invalidTraceLinesAreErrorsWithTheirLineNumber() throws Exception {
        String[][] cases = {
            {"{\"name\":\"Near\",\"type\":\"event\",\"value\":true,\"time\":1}\n\n{oops\n", ":3: error [trace]: not JSON: Unexpected character ('o' (code 111)): was expecting double-quote to start field name"},
            {"{\"name\":\"Near\",\"type\":\"event\",\"value\":true}\n", ":1: error [trace]: the record has no time (ms)"},
            {"{\"name\":\"Far\",\"type\":\"event\",\"value\":true,\"time\":1}\n", ":1: error [trace]: unknown context Far"},
            {"{\"name\":\"Near\",\"value\":true,\"time\":10}\n{\"name\":\"Near\",\"value\":true,\"time\":5}\n",
                ":2: error [trace]: time 5 is before the previous record's 10"},
        };
        for (String[] c : cases) {
            Path trace = dir.resolve("bad.jsonl");
            Files.writeString(trace, c[0]);
            Cli cli = new Cli();
            assertEquals(1, cli.run("roqme", "replay", p("worked.roqme.json"), "--trace", trace.toString()));
            assertEquals(trace + c[1], cli.err.toString().trim());
        }
    }

    @Test
    public void refusedModelsAndBadUsage() throws Exception {
        Path model = dir.resolve("bad.roqme.json");
        Files.writeString(model, Files.readString(dir.resolve("worked.roqme.json")).replace("\"belief\": \"autonomy\"", "\"belief\": \"nope\""));
        Cli cli = new Cli();
        assertEquals(1, cli.run("roqme", "replay", model.toString(), "--trace", p("worked.trace.jsonl")));
        assertEquals("worked.roqme:12:13: error [roqme-ref]: unknown belief nope", cli.err.toString().trim());
        Cli run = new Cli();
        assertEquals(2, run.run("roqme", "run", model.toString()));
        assertEquals("worked.roqme:12:13: error [roqme-ref]: unknown belief nope", run.err.toString().trim());
        assertEquals(2, Cli.exit("roqme", "replay", p("worked.roqme.json"), "--trace", p("none.jsonl")));
        assertEquals(2, Cli.exit("roqme", "replay", p("worked.roqme.json"), "--trace", p("worked.trace.jsonl"), "--format", "xml"));
        assertEquals(2, Cli.exit("roqme"));
    }

    /** A .roqme or .miron source is generated in memory: the same provider as on the generated file. */
    @Test
    public void replayTakesRoqmeAndMironSources() throws Exception {
        Path trace = dir.resolve("battery.jsonl");
        Files.writeString(trace, "{\"name\":\"BatteryLevel\",\"type\":\"number\",\"value\":90,\"time\":0}\n"
                + "{\"name\":\"BatteryLevel\",\"type\":\"number\",\"value\":25,\"time\":1500}\n");
        Path example = Cli.ROOT.resolve("examples/intralogistics");
        Cli roqme = new Cli();
        assertEquals(roqme.err.toString(), 0, roqme.run("roqme", "replay", example.resolve("intralogistics.roqme").toString(),
                "--trace", trace.toString()));
        String[] lines = roqme.out().split("\n");
        assertEquals("tick,time,safety,mission_completion,power_autonomy,fired", lines[0]);
        assertTrue(roqme.out(), lines[1].endsWith(",batteryHigh"));
        assertTrue(roqme.out(), lines[2].endsWith(",batteryLow:stillLow:batteryHalf")); // 25 < LowBattery 30 and < 60
        Cli miron = new Cli();
        assertEquals(miron.err.toString(), 0, miron.run("roqme", "replay", example.resolve("intralogistics.miron").toString(),
                "--trace", trace.toString()));
        assertEquals(roqme.out(), miron.out());
    }

    /** A source with an error is refused with file:line:col, by replay (1) and run (2), before anything runs. */
    @Test
    public void aSourceWithAnErrorIsRefusedWithItsPosition() throws Exception {
        Path bad = dir.resolve("bad.roqme");
        Files.writeString(bad, "roqme Bad\n\nproperty safety\nobservation near : Nope < 1 undermines safety\n");
        Cli replay = new Cli();
        assertEquals(1, replay.run("roqme", "replay", bad.toString(), "--trace", p("worked.trace.jsonl")));
        assertTrue(replay.err.toString(), replay.err.toString().matches("(?s).*bad\\.roqme:4:\\d+: error.*Nope.*"));
        Cli run = new Cli();
        assertEquals(2, run.run("roqme", "run", bad.toString()));
        assertTrue(run.err.toString(), run.err.toString().matches("(?s).*bad\\.roqme:4:\\d+: error.*Nope.*"));
    }
}
