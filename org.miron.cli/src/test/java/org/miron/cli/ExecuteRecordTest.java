package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import picocli.CommandLine;

/**
 * {@code miron execute TREE --record FILE.btlog} as a real process killed mid-run (SIGKILL): the
 * recording it leaves replays up to its last complete transition, also when the kill cut a
 * transition in two; a file that is not a recording is refused with the reason, exit 2.
 */
public class ExecuteRecordTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();


    @Test
    public void aRecordingCutShortByAKillReplaysUpToItsLastCompleteTransition() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("loop.xml");
        Files.writeString(tree, "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Main\"><Repeat num_cycles=\"-1\"><Sequence>"
                + "<Script code=\"n := 1\"/><Sleep msec=\"5\"/></Sequence></Repeat></BehaviorTree></root>");
        Path btlog = tmp.getRoot().toPath().resolve("loop.btlog");
        Endpoints ep = Endpoints.freeLoopback();
        Process p = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                CliProcess.classpath(), MironCli.class.getName(), "execute", tree.toString(), "--period", "5", "--record", btlog.toString(),
                "--request", ep.request(), "--bus-in", ep.busIn(), "--bus-out", ep.busOut(), "--skill-events", ep.skillEvents()))
                .redirectErrorStream(true).redirectOutput(tmp.getRoot().toPath().resolve("out.txt").toFile()).start();
        int header;
        try {
            header = awaitTransitions(btlog, 50, p);
        } finally {
            p.destroyForcibly(); // SIGKILL: nothing of the process runs after it
            assertTrue(p.waitFor(20, TimeUnit.SECONDS));
        }
        byte[] bytes = Files.readAllBytes(btlog);
        int complete = (bytes.length - header) / 9;
        String[] replayed = replay(btlog);
        assertEquals(replayed[1], "0", replayed[0]);
        assertTrue(replayed[1], replayed[1].contains(complete + " transitions over"));

        // a kill in the middle of a transition's write leaves part of it: the rest replays
        Path cut = tmp.getRoot().toPath().resolve("cut.btlog");
        Files.write(cut, Arrays.copyOf(bytes, header + (complete - 1) * 9 + 4));
        replayed = replay(cut);
        assertEquals(replayed[1], "0", replayed[0]);
        assertTrue(replayed[1], replayed[1].contains((complete - 1) + " transitions over"));
        assertTrue(replayed[1], replayed[1].contains("cut short: the last 4 bytes are an incomplete transition"));
    }

    /** Waits until the recording holds at least n transitions; returns the length of its header. */
    private static int awaitTransitions(Path btlog, int n, Process p) throws Exception {
        long end = System.currentTimeMillis() + 60_000;
        while (System.currentTimeMillis() < end && p.isAlive()) {
            if (Files.exists(btlog) && Files.size(btlog) > 23) {
                byte[] bytes = Files.readAllBytes(btlog);
                int header = 18 + 1 + 4 + ByteBuffer.wrap(bytes, 19, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() + 8;
                if (bytes.length >= header + 9 * n) {
                    return header;
                }
            }
            Thread.sleep(20);
        }
        throw new AssertionError("no " + n + " transitions recorded (process alive: " + p.isAlive() + ")");
    }

    @Test
    public void aFileThatIsNotARecordingIsRefusedWithTheReason() throws Exception {
        Path notOne = tmp.getRoot().toPath().resolve("notes.btlog");
        Files.writeString(notOne, "<root BTCPP_format=\"4\"/>\n");
        String[] replayed = replay(notOne);
        assertEquals("2", replayed[0]);
        assertTrue(replayed[1], replayed[1].contains("notes.btlog: not a BehaviorTree.CPP recording"));
        assertFalse(replayed[1], replayed[1].contains("Exception"));

        Path header = tmp.getRoot().toPath().resolve("header.btlog");
        Files.write(header, Arrays.copyOf("BTCPP4-FileLogger2\u0001\u00ff\u0000\u0000\u0000<root".getBytes("ISO-8859-1"), 28));
        replayed = replay(header);
        assertEquals("2", replayed[0]);
        assertTrue(replayed[1], replayed[1].contains("header is cut short"));
    }

    @Test
    public void recordRefusesAnotherExtensionAsTheLibraryDoes() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("t.xml");
        Files.writeString(tree, "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Main\"><AlwaysSuccess/></BehaviorTree></root>");
        StringWriter out = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(out, true));
        PrintStreamCapture err = PrintStreamCapture.start();
        int status;
        try {
            status = cli.execute("execute", tree.toString(), "--record", tmp.getRoot().toPath().resolve("run.log").toString());
        } finally {
            err.stop();
        }
        assertEquals(2, status);
        assertTrue(err.text(), err.text().contains("must end with .btlog"));
    }

    /** `miron replay FILE`: {exit status, what it printed}. */
    private static String[] replay(Path file) {
        StringWriter out = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(out, true));
        int status = cli.execute("replay", file.toString());
        return new String[] { Integer.toString(status), out.toString() };
    }

    /** System.err while a command that prints there runs (execute prints its errors on System.err). */
    private static final class PrintStreamCapture {
        private final java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        private final java.io.PrintStream saved = System.err;

        static PrintStreamCapture start() {
            PrintStreamCapture c = new PrintStreamCapture();
            System.setErr(new java.io.PrintStream(c.bytes, true));
            return c;
        }

        void stop() {
            System.setErr(saved);
        }

        String text() {
            return bytes.toString();
        }
    }
}
