package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.JsonSchemaFile;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * name.roqme.json, the runtime model the RoQME provider runs (docs/roqme-model.md): generated for
 * the examples' .roqme and .miron files, checked against docs/roqme-model.schema.json and shape by
 * shape against what the models say; imports are followed transitively; what the runtime model
 * cannot hold is refused with its position and nothing is written.
 */
public class RoqmeRuntimeModelTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final Path INTRALOGISTICS = Toolchain.ROOT.resolve("examples/intralogistics");
    private static final Path HOSPITAL = Toolchain.ROOT.resolve("examples/hospital-delivery");

    /** Generates model into a fresh folder and returns its runtime model, checked against the schema. */
    private JsonNode generate(Path model) throws IOException {
        Path out = temp.newFolder().toPath();
        Toolchain toolchain = new Toolchain();
        assertEquals(model + ": " + toolchain.messages(), 0, toolchain.generate(model.toString(), out.toString()));
        String base = model.getFileName().toString().replaceFirst("\\.(roqme|miron)$", "");
        return JsonSchemaFile.ROQME_MODEL.assertValid(out.resolve(base + ".roqme.json"));
    }

    /** An array context (the hospital example had one until issue 40: its world could not publish it). */
    @org.junit.Test
    public void anArrayContextKeepsItsCardinality() throws IOException {
        Path model = temp.newFolder().toPath().resolve("arrays.roqme");
        java.nio.file.Files.writeString(model, "roqme Arrays\n\n/** Speed readings of the last ten cycles. */\n"
                + "context speeds : number [10] (0:1.5)\n\nproperty comfort\n\n"
                + "observation fast : avg(speeds) > 0.8 undermines comfort\n");
        JsonNode generated = generate(model);
        assertEquals(json("{'kind':'number','lower':0,'upper':1.5,'cardinality':10}"), find(generated, "contexts", "speeds").get("type"));
    }

    /** JSON written with single quotes, for readable expectations. */
    private static JsonNode json(String text) throws IOException {
        return MAPPER.readTree(text.replace('\'', '"'));
    }

    private static JsonNode find(JsonNode model, String kind, String id) {
        for (JsonNode declaration : model.get(kind)) {
            if (declaration.get("id").asText().equals(id)) {
                return declaration;
            }
        }
        throw new AssertionError("no " + kind + " '" + id + "' in " + model.get(kind));
    }

    private static List<String> ids(JsonNode model, String kind) {
        List<String> ids = new ArrayList<>();
        model.get(kind).forEach(d -> ids.add(d.get("id").asText()));
        return ids;
    }

    /** "file:line:col" of the first occurrence of word after prefix in a file. */
    private static String at(Path file, String prefix, String word) throws IOException {
        List<String> lines = Files.readAllLines(file);
        for (int i = 0; i < lines.size(); i++) {
            int column = lines.get(i).indexOf(prefix + word);
            if (column >= 0) {
                return file.getFileName() + ":" + (i + 1) + ":" + (column + prefix.length() + 1);
            }
        }
        throw new AssertionError(prefix + word + " not in " + file);
    }

    @Test
    public void intralogisticsRoqmeHasEveryDeclarationInOrder() throws IOException {
        Path roqme = INTRALOGISTICS.resolve("intralogistics.roqme");
        JsonNode model = generate(roqme);
        assertEquals("intralogistics", model.get("model").asText());
        assertEquals("intralogistics.roqme", model.get("source").asText());
        assertEquals(List.of("BatteryLevel", "ObstacleDistance", "HumanDistance", "FreeSpace", "Docked", "DeliveryDone",
                "EmergencyStop", "HumanNearby"), ids(model, "contexts"));
        assertEquals(List.of("safety", "mission_completion", "power_autonomy"), ids(model, "beliefs"));
        assertEquals(List.of("tooClose", "personNearby", "emergency", "openSpace", "delivered", "idle", "batteryLow",
                "stillLow", "batteryHigh", "batteryHalf", "charging", "recharged"), ids(model, "observations"));
        JsonNode safety = find(model, "beliefs", "safety");
        assertEquals("Intralogistics", safety.get("namespace").asText());
        assertEquals(at(roqme, "property ", "safety"), safety.get("at").asText());
        assertEquals(at(roqme, "observation ", "charging"), find(model, "observations", "charging").get("at").asText());
    }

    @Test
    public void intralogisticsShapes() throws IOException {
        JsonNode model = generate(INTRALOGISTICS.resolve("intralogistics.roqme"));
        // postfix x'increasing(5): a call with the receiver first; `and` of a boolean and a call: event logic
        assertEquals(json("{'op':'and','left':{'ref':'Docked','type':'boolean'},'right':{'call':'increasing',"
                + "'args':[{'ref':'BatteryLevel','type':'number'},{'number':5,'type':'number'}],'type':'boolean'},"
                + "'type':'boolean'}"), find(model, "observations", "charging").get("pattern"));
        assertEquals(json("{'op':'and','left':{'op':'=','left':{'ref':'FreeSpace','type':'enum'},"
                + "'right':{'enum':'HIGH','enumType':'AvailableSpace','type':'enum'},'type':'boolean'},"
                + "'right':{'op':'>','left':{'ref':'ObstacleDistance','type':'number'},'right':{'number':3,'type':'number'},"
                + "'type':'boolean'},'type':'boolean'}"), find(model, "observations", "openSpace").get("pattern"));
        // a derived context
        JsonNode nearby = find(model, "contexts", "HumanNearby");
        assertEquals(json("{'kind':'boolean'}"), nearby.get("type"));
        assertEquals(json("{'op':'<','left':{'ref':'HumanDistance','type':'number'},'right':{'number':1.5,'type':'number'},"
                + "'type':'boolean'}"), nearby.get("derived"));
        assertFalse(find(model, "contexts", "BatteryLevel").has("derived"));
        assertEquals(json("{'kind':'number','lower':0,'upper':100,'unit':'%'}"), find(model, "contexts", "BatteryLevel").get("type"));
        assertEquals(json("{'kind':'enum','literals':['LOW','MEDIUM','HIGH']}"), find(model, "contexts", "FreeSpace").get("type"));
        assertEquals(json("{'kind':'eventtype'}"), find(model, "contexts", "DeliveryDone").get("type"));
        // param, var (a time window in ms), timer
        assertEquals(json("{'number':30,'type':'number'}"), find(model, "params", "LowBattery").get("default"));
        assertEquals(json("{'call':'count','args':[{'ref':'DeliveryDone','type':'event'},{'time':600000,'type':'time'}],"
                + "'type':'number'}"), find(model, "vars", "recentDeliveries").get("init"));
        JsonNode timer = find(model, "timers", "sinceLastDelivery");
        assertEquals(1_200_000, timer.get("periodMs").asInt());
        assertTrue(timer.get("schedule").isNull());
        assertEquals(0, timer.get("offsetMs").asInt());
        assertTrue(timer.get("onetime").asBoolean());
        assertTrue(timer.get("paused").asBoolean());
        // beliefs: reference 0.5 when omitted, survival in ms or null
        assertEquals(0.7, find(model, "beliefs", "safety").get("reference").asDouble(), 0);
        assertTrue(find(model, "beliefs", "safety").get("survivalMs").isNull());
        assertEquals(1_800_000, find(model, "beliefs", "mission_completion").get("survivalMs").asInt());
        assertEquals(0.5, find(model, "beliefs", "power_autonomy").get("reference").asDouble(), 0);
        assertEquals("property", find(model, "beliefs", "power_autonomy").get("kind").asText());
        assertTrue(find(model, "beliefs", "power_autonomy").get("expr").isNull());
        // actions: strengths (MEDIUM when omitted), survival of the action, timer actions
        assertEquals(json("[{'kind':'undermines','belief':'safety','strength':'VERYHIGH','survivalMs':300000}]"),
                find(model, "observations", "emergency").get("actions"));
        assertEquals(json("[{'kind':'reinforces','belief':'mission_completion','strength':'MEDIUM','survivalMs':null},"
                + "{'kind':'starts','timer':'sinceLastDelivery'}]"), find(model, "observations", "delivered").get("actions"));
        assertEquals("LOW", find(model, "observations", "openSpace").get("actions").get(0).get("strength").asText());
        assertEquals(json("{'ref':'sinceLastDelivery','type':'event'}"), find(model, "observations", "idle").get("pattern"));
        assertEquals("Emergency stops are strong evidence against safety.",
                find(model, "observations", "emergency").get("doc").asText());
        assertFalse(find(model, "observations", "batteryHigh").has("doc"));
    }

    @Test
    public void anObservationReadingAVarpointIsRefused() throws IOException {
        Path dir = temp.newFolder("vp").toPath();
        Path model = dir.resolve("m.miron");
        Files.writeString(model, """
                miron M
                property p
                @varpoint speed : number (1:1:3)
                observation fast : speed > 2 reinforces p
                """);
        Path out = temp.newFolder("vp-out").toPath();
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 1, toolchain.generate(model.toString(), out.toString()));
        assertTrue(toolchain.messages(), toolchain.messages().contains(
                "m.miron:4:20: error [roqme.unsupported-varpoint]: the RoQME provider does not know varpoint 'speed'"));
        try (var files = Files.list(out)) {
            assertEquals(List.of(), files.toList());
        }
    }

    @Test
    public void everyRefusalCodeIsDocumented() throws Exception {
        String doc = Files.readString(Toolchain.ROOT.resolve("docs/issue-codes.md"));
        int codes = 0;
        for (java.lang.reflect.Field field : RoqmeRuntimeModel.class.getFields()) {
            if (field.getType() == String.class && ((String) field.get(null)).startsWith("roqme.")) {
                codes++;
                String code = (String) field.get(null);
                assertTrue(code, code.matches("roqme\\.unsupported-[a-z0-9]+(-[a-z0-9]+)*"));
                assertTrue(code + " is not in docs/issue-codes.md", doc.contains("| `" + code + "` |"));
            }
        }
        assertEquals(6, codes);
    }

    /** The schema is no formality: what the provider could not read breaks it. */
    @Test
    public void theSchemaRefusesWhatTheProviderCouldNotRead() throws IOException {
        JsonNode model = generate(INTRALOGISTICS.resolve("intralogistics.roqme"));
        List<java.util.function.Consumer<com.fasterxml.jackson.databind.node.ObjectNode>> breakages = List.of(
                m -> ((com.fasterxml.jackson.databind.node.ObjectNode) m.get("contexts").get(0)).remove("at"),
                m -> ((com.fasterxml.jackson.databind.node.ObjectNode) m.get("observations").get(1).get("actions").get(0))
                        .put("strength", "STRONG"),
                m -> ((com.fasterxml.jackson.databind.node.ObjectNode) m.get("observations").get(0).get("pattern"))
                        .put("op", "xor"),
                m -> ((com.fasterxml.jackson.databind.node.ObjectNode) m.get("observations").get(0).get("pattern").get("left"))
                        .remove("type"),
                m -> ((com.fasterxml.jackson.databind.node.ObjectNode) m.get("timers").get(0)).put("schedule", "0 8 * * *"),
                m -> ((com.fasterxml.jackson.databind.node.ObjectNode) m.get("beliefs").get(0)).put("reference", 1.5),
                m -> m.put("extra", true));
        for (int i = 0; i < breakages.size(); i++) {
            com.fasterxml.jackson.databind.node.ObjectNode broken = (com.fasterxml.jackson.databind.node.ObjectNode) model.deepCopy();
            breakages.get(i).accept(broken);
            assertFalse("breakage " + i + " passes the schema", JsonSchemaFile.ROQME_MODEL.problems(broken).isEmpty());
        }
    }

    @Test
    public void intralogisticsMironCarriesTheImportedRoqmeBesideTheIoJson() throws IOException {
        Path out = temp.newFolder().toPath();
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 0,
                toolchain.generate(INTRALOGISTICS.resolve("intralogistics.miron").toString(), out.toString()));
        assertTrue(Files.isRegularFile(out.resolve("intralogistics.io.json")));
        JsonNode fromMiron = JsonSchemaFile.ROQME_MODEL.assertValid(out.resolve("intralogistics.roqme.json"));
        JsonNode fromRoqme = generate(INTRALOGISTICS.resolve("intralogistics.roqme"));
        assertEquals("intralogistics.miron", fromMiron.get("source").asText());
        for (String kind : List.of("contexts", "params", "vars", "timers", "beliefs", "observations")) {
            assertEquals(kind, fromRoqme.get(kind), fromMiron.get(kind));
        }
    }

    @Test
    public void hospitalShapes() throws IOException {
        JsonNode model = generate(HOSPITAL.resolve("hospital.roqme"));
        JsonNode comfort = find(model, "beliefs", "comfort");
        assertEquals(0.7, comfort.get("reference").asDouble(), 0);
        assertEquals(json("{'kind':'number'}"), comfort.get("type"));
        assertEquals(json("{'op':'-','left':{'number':1,'type':'number'},'right':{'op':'/','left':"
                + "{'ref':'recentNearMisses','type':'number'},'right':{'number':10,'type':'number'},'type':'number'},"
                + "'type':'number'}"), comfort.get("expr"));
        JsonNode complaints = find(model, "beliefs", "staffComplaints");
        assertEquals("beliefvar", complaints.get("kind").asText());
        assertEquals(3_600_000, complaints.get("survivalMs").asInt());
        assertEquals(0.5, find(model, "beliefs", "autonomy").get("reference").asDouble(), 0);
        assertEquals(json("[{'kind':'undermines','belief':'safety','strength':'HIGH','survivalMs':600000},"
                + "{'kind':'undermines','belief':'comfort','strength':'MEDIUM','survivalMs':null},"
                + "{'kind':'reinforces','belief':'staffComplaints','strength':'LOW','survivalMs':null}]"),
                find(model, "observations", "nearMisses").get("actions"));
        assertEquals(json("[{'kind':'starts','timer':'sinceDelivery'},{'kind':'clears','belief':'staffComplaints'}]"),
                find(model, "observations", "handedOver").get("actions"));
        assertEquals(json("{'op':'while','arg':{'ref':'delivered','type':'event'},'cond':{'op':'<','left':"
                + "{'ref':'missionTime','type':'time'},'right':{'ref':'maxMissionTime','type':'time'},'type':'boolean'},"
                + "'type':'boolean'}"), find(model, "observations", "onTime").get("pattern"));
        // a timer while value logic & of a postfix call over a time window and a derived context
        assertEquals(json("{'op':'while','arg':{'ref':'batteryCheck','type':'event'},'cond':{'op':'&','left':"
                + "{'call':'decreasing','args':[{'ref':'battery','type':'number'},{'time':300000,'type':'time'}],"
                + "'type':'boolean'},'right':{'ref':'lowBattery','type':'boolean'},'type':'boolean'},'type':'boolean'}"),
                find(model, "observations", "draining").get("pattern"));
        // an enum declared inline is named after its context
        assertEquals(json("{'enum':'night','enumType':'shift','type':'enum'}"),
                find(model, "observations", "nightDriving").get("pattern").get("left").get("right"));
        assertEquals(json("{'kind':'number','lower':0,'upper':1.5,'unit':'m/s'}"), find(model, "contexts", "speed").get("type"));
        assertEquals(json("{'kind':'time','upper':3600}"), find(model, "contexts", "missionTime").get("type"));
        assertEquals(json("{'kind':'number','lower':0,'upper':100,'unit':'%'}"), find(model, "contexts", "battery").get("type"));
        assertEquals(json("{'time':900000,'type':'time'}"), find(model, "params", "maxMissionTime").get("default"));
        assertEquals(json("{'boolean':false,'type':'boolean'}"), find(model, "params", "quietHours").get("default"));
        JsonNode timer = find(model, "timers", "sinceDelivery");
        assertEquals(3_600_000, timer.get("periodMs").asInt());
    }

    @Test
    public void hospitalMironFollowsTheSchema() throws IOException {
        JsonNode model = generate(HOSPITAL.resolve("hospital.miron"));
        assertEquals(List.of("safety", "timeliness", "autonomy", "comfort", "staffComplaints").stream().sorted().toList(),
                ids(model, "beliefs").stream().sorted().toList());
        assertEquals("Hospital", find(model, "beliefs", "safety").get("namespace").asText());
    }

    @Test
    public void importsAreFollowedTransitivelyAndSharedNamesGetTheirNamespace() throws IOException {
        Path dir = temp.newFolder("models").toPath();
        Files.writeString(dir.resolve("a.roqme"), """
                roqme A
                context level : number
                property safety reference 0.4
                """);
        Files.createDirectories(dir.resolve("lib"));
        Files.writeString(dir.resolve("lib/b.roqme"), """
                roqme B
                import "../a.roqme"
                property safety survival 2 minutes
                observation low : A.level < 3 { undermines A.safety high reinforces safety }
                """);
        Files.writeString(dir.resolve("top.miron"), """
                miron Top
                import "lib/b.roqme" as b
                context docked : boolean
                observation dock : docked clears b.safety
                """);
        JsonNode model = generate(dir.resolve("top.miron"));
        assertEquals(List.of("level", "docked"), ids(model, "contexts"));
        assertEquals(List.of("A.safety", "B.safety"), ids(model, "beliefs"));
        assertEquals("A", find(model, "contexts", "level").get("namespace").asText());
        assertEquals("Top", find(model, "contexts", "docked").get("namespace").asText());
        assertEquals("a.roqme:2:9", find(model, "contexts", "level").get("at").asText());
        assertEquals(json("[{'kind':'undermines','belief':'A.safety','strength':'HIGH','survivalMs':null},"
                + "{'kind':'reinforces','belief':'B.safety','strength':'MEDIUM','survivalMs':null}]"),
                find(model, "observations", "low").get("actions"));
        assertEquals(json("{'kind':'clears','belief':'B.safety'}"), find(model, "observations", "dock").get("actions").get(0));
        assertEquals(json("{'op':'<','left':{'ref':'level','type':'number'},'right':{'number':3,'type':'number'},"
                + "'type':'boolean'}"), find(model, "observations", "low").get("pattern"));
    }

    @Test
    public void aTimerWithAComputedPeriodIsRefusedWithItsPositionAndNothingIsWritten() throws IOException {
        Path dir = temp.newFolder("bad").toPath();
        Path model = dir.resolve("bad.roqme");
        Files.writeString(model, """
                roqme Bad
                param every : time default 5 seconds
                timer tick := every
                property p
                observation o : tick reinforces p
                """);
        Path out = temp.newFolder("bad-out").toPath();
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 1, toolchain.generate(model.toString(), out.toString()));
        assertTrue(toolchain.messages(), toolchain.messages().contains(
                "bad.roqme:3:15: error [roqme.unsupported-timer-period]: the period of timer 'tick' must be a time literal"));
        try (var files = Files.list(out)) {
            assertEquals(List.of(), files.toList());
        }
    }
}
