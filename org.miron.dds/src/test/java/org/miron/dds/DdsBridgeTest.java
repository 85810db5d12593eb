package org.miron.dds;

import static org.junit.Assert.assertEquals;
import static org.junit.Assume.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.BeforeClass;
import org.junit.Test;

/**
 * The bridge against Cyclone DDS (PyPI), each scenario of {@link DdsScenarios} in a JVM of its own
 * inside a private network namespace with only {@code lo} ({@code unshare -n}; multicast on lo, so
 * discovery works and nothing leaves the machine). Skipped, saying why, when the peer's python or
 * the namespace cannot be had (CI installs the first with scripts/ensure-cyclonedds.sh and runs as root).
 */
public class DdsBridgeTest {
    private static final String NETNS_SETUP = "ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo";
    private static String skip;

    @BeforeClass
    public static void check() throws Exception {
        String python = System.getProperty("dds.python", "python3");
        if (!new File(python).canExecute() || run(List.of(python, "-c", "import cyclonedds")) != 0) {
            skip = "no python with cyclonedds at " + python + " (scripts/ensure-cyclonedds.sh could not install it)";
        } else if (run(List.of("unshare", "-n", "sh", "-c", NETNS_SETUP)) != 0) {
            skip = "cannot create a private network namespace (unshare -n needs root or user namespaces)";
        }
        if (skip != null) {
            System.err.println("DdsBridgeTest skipped: " + skip);
        }
    }

    private static int run(List<String> cmd) throws Exception {
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        return p.waitFor(60, TimeUnit.SECONDS) ? p.exitValue() : -1;
    }

    private static void scenario(String name) throws Exception {
        assumeTrue(skip, skip == null);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String cp = System.getProperty("dds.test.classpath", System.getProperty("java.class.path"));
        String home = System.getProperty("dds.home", System.getProperty("java.io.tmpdir") + "/dds-home");
        Files.createDirectories(Path.of(home));
        String cmd = NETNS_SETUP + " && exec \"$0\" \"$@\"";
        Process p = new ProcessBuilder(List.of("unshare", "-n", "sh", "-c", cmd, java, "-Xmx512m", "-Duser.home=" + home,
                "-Ddds.python=" + System.getProperty("dds.python", "python3"), "-Dmiron.root=" + System.getProperty("miron.root", "."),
                "-cp", cp, NetnsMain.class.getName(), name)).redirectErrorStream(true).start();
        byte[] out = p.getInputStream().readAllBytes(); // until the scenario JVM exits
        boolean done = p.waitFor(300, TimeUnit.SECONDS);
        String text = new String(out, StandardCharsets.UTF_8);
        if (!done) {
            p.destroyForcibly();
        }
        assertEquals("scenario " + name + " in its namespace:\n" + text, 0, done ? p.exitValue() : -1);
    }

    @Test
    public void batteryMovesTheMetricAndTheDecision() throws Exception {
        scenario("batteryMovesTheMetricAndTheDecision");
    }

    @Test
    public void roqmeTypesBothWays() throws Exception {
        scenario("roqmeTypesBothWays");
    }

    @Test
    public void exampleRobotClosesTheLoop() throws Exception {
        scenario("exampleRobotClosesTheLoop");
    }

    @Test
    public void robotWithItsOwnTypesClosesTheLoop() throws Exception {
        scenario("robotWithItsOwnTypesClosesTheLoop");
    }

    @Test
    public void keySwitchRefusesWhatItDoesNotRecognise() throws Exception {
        scenario("keySwitchRefusesWhatItDoesNotRecognise");
    }

    @Test
    public void unkeyedRoqmeTopicsWhenConfigured() throws Exception {
        scenario("unkeyedRoqmeTopicsWhenConfigured");
    }

    @Test
    public void malformedFieldsAreCountedAndDropped() throws Exception {
        scenario("malformedFieldsAreCountedAndDropped");
    }

    @Test
    public void restartLosesNoDecisionAndAPeerComesBack() throws Exception {
        scenario("restartLosesNoDecisionAndAPeerComesBack");
    }
}
