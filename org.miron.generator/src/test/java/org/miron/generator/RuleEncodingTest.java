package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * How rules reach MiniZinc (docs/generators.md), solved by the real minizinc: a comparison over
 * two varpoints becomes a set of index pairs, one over three varpoints of 101 values (over
 * ExpressionToMiniZinc.TABLE_LIMIT combinations) keeps float arithmetic, and sqrt of a negative
 * context makes its comparison false instead of aborting the solve. Utilities rise linearly with
 * each value, so the optimum uses all the room the rules leave.
 */
public class RuleEncodingTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();

    private static Path out;
    private static String mzn;

    @BeforeClass
    public static void generate() throws IOException {
        Path models = Toolchain.copyResources("weaving", temp.newFolder("models").toPath());
        Files.writeString(models.resolve("room.miron"), "import \"nominal.bt\" as bt\n\n"
                + "property p\ncontext c0 : number (0:10)\n\n"
                + "@varpoint a : number (0:1:100) { 100 affects p+++ }\n"
                + "@varpoint b : number (0:1:100) { 100 affects p+++ }\n"
                + "@varpoint c : number (0:1:100) { 100 affects p+++ }\n"
                + "rule pair : implies a + b <= 50\n"
                + "rule triple : implies a + b + c <= 120\n"
                + "rule root : sqrt(c0 - 5) > 1 implies c <= 10\n");
        out = temp.newFolder("out").toPath();
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 0, toolchain.generate(models.resolve("room.miron").toString(), out.toString()));
        mzn = Files.readString(out.resolve("room.mzn"));
    }

    private static int value(MiniZinc m, Map<String, Integer> d, String vp) {
        return (int) Double.parseDouble(m.value(vp, d));
    }

    @Test
    public void theEncodingFollowsTheNumberOfCombinations() {
        assertTrue(mzn, mzn.contains("((a_var * b_n + b_var) in {(a_i * b_n + b_i) | a_i in 0..a_n-1, b_i in 0..b_n-1 where "));
        assertTrue(mzn, mzn.contains("a_x[a_var] + b_x[b_var]) + c_x[c_var]) <= 120.0"));
        assertTrue(mzn, mzn.contains("(miron_sqrt((context_c0 - 5.0)) > 1.0)"));
    }

    @Test
    public void bothEncodingsConstrainTheOptimum() {
        MiniZinc m = new MiniZinc(out.resolve("room.io.json"));
        Map<String, Integer> d = m.solve(m.defaults());
        int a = value(m, d, "a"), b = value(m, d, "b"), c = value(m, d, "c");
        assertTrue(d.toString(), a + b <= 50);
        assertEquals(d.toString(), 120, a + b + c);
    }

    @Test
    public void anUndefinedSquareRootLeavesItsRuleInactive() {
        MiniZinc m = new MiniZinc(out.resolve("room.io.json"));
        ObjectNode data = m.defaults();
        data.put("context_c0_known", true);
        data.put("context_c0", 2.0); // sqrt(-3): undefined, so false: c is free
        Map<String, Integer> d = m.solve(data);
        assertEquals(d.toString(), 120, value(m, d, "a") + value(m, d, "b") + value(m, d, "c"));
        data.put("context_c0", 9.0); // sqrt(4) = 2 > 1: c at most 10
        d = m.solve(data);
        assertEquals(d.toString(), 10, value(m, d, "c"));
        assertEquals(d.toString(), 50, value(m, d, "a") + value(m, d, "b"));
    }
}
