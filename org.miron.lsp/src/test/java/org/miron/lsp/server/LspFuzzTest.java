package org.miron.lsp.server;

import static org.junit.Assert.assertTrue;

import org.junit.Test;

/**
 * Half-written files never make the server fail: a few hundred seeded random edits on the
 * examples and on BehaviorTree.CPP 4 trees, every request kind asked every ten edits, zero internal
 * errors and the server alive afterwards. Latencies are the soak task's business (`lspFuzz`).
 */
public class LspFuzzTest {

    private static void fuzz(long seed) throws Exception {
        try (LspFuzzer fuzzer = new LspFuzzer(seed)) {
            fuzzer.run(150, 10);
            assertTrue("internal errors with seed " + seed + ":\n" + String.join("\n", fuzzer.internalErrors),
                    fuzzer.internalErrors.isEmpty());
            assertTrue("the server stopped answering", fuzzer.alive());
        }
    }

    @Test
    public void seed1() throws Exception {
        fuzz(1);
    }

    @Test
    public void seed29() throws Exception {
        fuzz(29);
    }
}
