package org.miron.testkit;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.Assume;

/**
 * The Python that runs the real BehaviorTree.CPP 4 (behaviortreepy): the virtual environment that
 * scripts/ensure-btcpp4.sh makes at build/btcpp4-venv. Both version-4 oracles (the loader in this
 * kit, the tick oracle in org.miron.executor's tests) start it; a test needing it is skipped, with
 * the reason printed, when it is missing.
 */
public final class Btcpp4Python {
    private Btcpp4Python() {
    }

    /** Where the environment's python is, installed or not. */
    public static Path location() {
        return RepositoryRoot.resolve("build/btcpp4-venv/bin/python");
    }

    /** Whether the environment is installed. */
    public static boolean installed() {
        return Files.isExecutable(location());
    }

    /** The python; skips the calling test, saying why, when it is not installed. */
    public static Path assumeInstalled() {
        if (!installed()) {
            String reason = "BehaviorTree.CPP 4 oracle not installed (no " + location()
                    + "; scripts/ensure-btcpp4.sh installs it, pip must reach behaviortreepy): test skipped";
            System.out.println(reason);
            Assume.assumeTrue(reason, false);
        }
        return location();
    }
}
