package org.miron.dds;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.File;
import java.nio.file.Path;

/**
 * One Cyclone codec peer ({@link CyclonePeer#codec}) for tests outside this package: Cyclone's own
 * CDR of a message and its reading of ours, no DDS domain joined (so no network namespace needed).
 */
public final class CodecPeers {
    private static CyclonePeer peer;
    private static String skip;

    private CodecPeers() {
    }

    /** Starts the peer, or returns null when there is no python with cyclonedds ({@link #skip} says so). */
    public static synchronized AutoCloseable start(Path dir) throws Exception {
        String python = System.getProperty("dds.python", "python3");
        if (!new File(python).canExecute() || new ProcessBuilder(python, "-c", "import cyclonedds").redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start().waitFor() != 0) {
            skip = "no python with cyclonedds at " + python + " (scripts/ensure-cyclonedds.sh)";
            System.err.println("skipped: " + skip);
            return null;
        }
        peer = CyclonePeer.codec(dir);
        return peer;
    }

    public static String skip() {
        return skip;
    }

    public static String encode(String type, String data, boolean xcdr2, boolean appendable) throws Exception {
        return peer.encode(type, data, xcdr2, appendable);
    }

    public static JsonNode decode(String type, String hex) throws Exception {
        return peer.decode(type, hex);
    }
}
