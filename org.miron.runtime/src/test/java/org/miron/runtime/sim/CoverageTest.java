package org.miron.runtime.sim;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.TextNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.executor.Tree;
import org.miron.executor.TreeContext;
import org.miron.executor.skills.VariantSource;
import org.miron.runtime.Json;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.RuleSpec;
import org.miron.runtime.engine.VariationPoint;

/**
 * The coverage counts on a tree, a varpoint and rules small enough to know the answer: a Fallback
 * whose first child fails and whose second, a Sequence of two same-named nodes, succeeds, so its
 * third child never runs; a variant in force 30 % of the time; a rule applied in one decision of two.
 */
public class CoverageTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private static final String TREE = "<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\n"
            + "  <BehaviorTree ID=\"Main\">\n"
            + "    <Fallback>\n"
            + "      <AlwaysFailure/>\n"
            + "      <Sequence>\n"
            + "        <AlwaysSuccess/>\n"
            + "        <AlwaysSuccess/>\n"
            + "      </Sequence>\n"
            + "      <AlwaysSuccess name=\"never\"/>\n"
            + "    </Fallback>\n"
            + "  </BehaviorTree>\n"
            + "</root>\n";

    private static final VariationPoint TASK = new VariationPoint("task", "enum", List.of(TextNode.valueOf("pick"),
            TextNode.valueOf("dock")), 0, "task_d", null, null, null, null, null);

    private int files;

    private Coverage run(int missions) throws Exception {
        Path file = tmp.newFile("tiny" + files++ + ".xml").toPath();
        Files.writeString(file, TREE);
        long[] now = { 0 };
        Tree tree = Setup.buildTree(file, new TreeContext(() -> now[0]), new VariantSource(), spec -> {
            throw new IllegalStateException("no skills here");
        });
        IoModel io = new IoModel("tiny", null, null, List.of(), List.of(TASK),
                List.of(new RuleSpec("low", null), new RuleSpec("crowded", null)), "need", null);
        CoverageRecorder recorder = new CoverageRecorder(tree, io);
        tree.addListener(recorder);
        for (int i = 0; i < missions; i++) {
            recorder.beforeRootTick();
            tree.tickRoot();
        }
        recorder.varpoint(TASK, TextNode.valueOf("pick"), 0);
        recorder.varpoint(TASK, TextNode.valueOf("dock"), 3000);
        ArrayNode applied = Json.MAPPER.createArrayNode();
        applied.addObject().put("rule", "low");
        recorder.decision(applied);
        recorder.decision(Json.MAPPER.createArrayNode());
        return recorder.finish(10_000);
    }

    @Test
    public void theCountsOfATinyTreeVariantAndRules() throws Exception {
        Coverage c = run(3);
        assertEquals(List.of("Main/Fallback", "Main/Fallback/AlwaysFailure", "Main/Fallback/Sequence",
                "Main/Fallback/Sequence/AlwaysSuccess[0]", "Main/Fallback/Sequence/AlwaysSuccess[1]", "Main/Fallback/never"), c.nodes());
        assertEquals(3, c.missions());
        long[][] expected = { { 3, 3, 0 }, { 3, 0, 3 }, { 3, 3, 0 }, { 3, 3, 0 }, { 3, 3, 0 }, { 0, 0, 0 } };
        for (int i = 0; i < expected.length; i++) {
            assertEquals(c.nodes().get(i), expected[i][0], c.ticked(i));
            assertEquals(c.nodes().get(i), expected[i][1], c.succeeded(i));
            assertEquals(c.nodes().get(i), expected[i][2], c.failed(i));
        }
        assertEquals(List.of("task::pick", "task::dock"), c.variants());
        assertEquals(3000, c.heldMs(0));
        assertEquals(7000, c.heldMs(1));
        assertEquals(List.of(1L, 0L), List.of(c.applied(0), c.applied(1)));
        assertEquals(2, c.decisions());
        List<Coverage.Item> items = c.items();
        assertEquals(10, items.size());
        assertEquals(1.0, items.get(0).share(), 0);
        assertEquals(false, items.get(5).covered());
        assertEquals(0.3, items.get(6).share(), 1e-12);
        assertEquals(0.5, items.get(8).share(), 0);
        assertEquals(false, items.get(9).covered());
        assertEquals(8, c.covered());
        assertEquals(0.8, c.coveredShare(), 1e-12);
    }

    @Test
    public void runsMergeBySummingAndTheGateSaysWhichPolicyFallsShort() throws Exception {
        Coverage one = run(3);
        Coverage merged = Coverage.merge(List.of(one, run(2)));
        assertEquals(5, merged.missions());
        assertEquals(5, merged.failed(1));
        assertEquals(20_000, merged.durationMs());
        assertEquals(4, merged.decisions());
        List<CoverageTable.Column> columns = List.of(new CoverageTable.Column("adaptive", merged));
        assertEquals(List.of(), CoverageTable.belowMinimum(columns, 80));
        assertEquals(List.of("coverage of adaptive is 80.0 % (8 of 10 items), below --min-coverage 80.5 %"),
                CoverageTable.belowMinimum(columns, 80.5));
        String table = CoverageTable.table(columns);
        assertEquals(table, "coverage  item                                     adaptive", table.split("\n")[0]);
        assertEquals(table, "node      Main/Fallback/AlwaysFailure              100.0 %  ticked 5, S 0, F 5", table.split("\n")[2]);
        assertEquals(table, "node      Main/Fallback/never                        0.0 %  ticked 0, S 0, F 0", table.split("\n")[6]);
        assertEquals(table, "variant   task::dock                                70.0 %", table.split("\n")[8]);
        assertEquals(table, "rule      low                                       50.0 %  2 of 4 decisions", table.split("\n")[9]);
        assertEquals(table, "          covered                                  8 of 10 (80.0 %)", table.split("\n")[11]);
        String json = Json.MAPPER.writeValueAsString(CoverageTable.json(columns));
        assertTrue(json, json.startsWith("{\"adaptive\":{\"items\":10,\"covered\":8,\"share\":0.8,\"missions\":5,\"decisions\":4,\"nodes\":["
                + "{\"path\":\"Main/Fallback\",\"ticked\":5,\"success\":5,\"failure\":0,\"missions\":5,\"share\":1.0}"));
    }
}
