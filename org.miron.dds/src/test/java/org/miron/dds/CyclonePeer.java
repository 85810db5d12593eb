package org.miron.dds;

import static org.junit.Assert.assertNotNull;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

/**
 * The independent DDS peer: dds_peer.py (Cyclone DDS from PyPI) as a child process, driven one
 * JSON line at a time; every event it prints is kept, and waits are on those events.
 */
final class CyclonePeer implements AutoCloseable {
    static final long TIMEOUT = 60_000;
    /** Cyclone on the namespace's loopback, multicast included (docs/dds.md, pitfall 2). */
    static final String CYCLONE_CONFIG = "<CycloneDDS><Domain id=\"any\"><General><Interfaces>"
            + "<NetworkInterface name=\"lo\" multicast=\"true\"/></Interfaces></General></Domain></CycloneDDS>";
    private static final ObjectMapper JSON = new ObjectMapper();

    private final Process process;
    private final Writer in;
    private final List<JsonNode> events = new ArrayList<>();
    private int seen; // events before this index were consumed by awaitEvent

    CyclonePeer(Path dir) throws IOException, InterruptedException {
        this(dir, List.of());
    }

    /** The peer as an encoder and decoder only ({@code --codec}): Cyclone's CDR without joining a domain, so it runs anywhere. */
    static CyclonePeer codec(Path dir) throws IOException, InterruptedException {
        return new CyclonePeer(dir, List.of("--codec"));
    }

    private CyclonePeer(Path dir, List<String> args) throws IOException, InterruptedException {
        Path script = dir.resolve("dds_peer.py");
        try (InputStream s = CyclonePeer.class.getResourceAsStream("dds_peer.py")) {
            Files.copy(s, script, StandardCopyOption.REPLACE_EXISTING);
        }
        List<String> cmd = new ArrayList<>(List.of(System.getProperty("dds.python", "python3"), "-u", script.toString()));
        cmd.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().put("CYCLONEDDS_URI", CYCLONE_CONFIG);
        pb.redirectError(ProcessBuilder.Redirect.INHERIT);
        process = pb.start();
        in = new java.io.OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8);
        Thread reader = new Thread(this::read, "cyclone-peer");
        reader.setDaemon(true);
        reader.start();
        assertNotNull("the Cyclone peer starts", awaitEvent(e -> e.path("event").asText().equals("ready")));
    }

    private void read() {
        try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = r.readLine()) != null) {
                JsonNode e;
                try {
                    e = JSON.readTree(line);
                } catch (IOException ex) {
                    System.err.println("peer: " + line);
                    continue;
                }
                if (e.path("event").asText().equals("error")) {
                    System.err.println("peer error: " + e);
                }
                synchronized (this) {
                    events.add(e);
                    notifyAll();
                }
            }
        } catch (IOException ignored) {
            // the peer was stopped
        }
    }

    void send(String json) throws IOException {
        in.write(json.replace('\n', ' ') + "\n");
        in.flush();
    }

    /** The first event after the last one returned that matches. */
    synchronized JsonNode awaitEvent(Predicate<JsonNode> p) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        while (true) {
            for (int i = seen; i < events.size(); i++) {
                if (p.test(events.get(i))) {
                    seen = i + 1;
                    return events.get(i);
                }
            }
            long left = end - System.currentTimeMillis();
            if (left <= 0 || !process.isAlive() && seen >= events.size()) {
                return null;
            }
            wait(Math.min(left, 200));
        }
    }

    /** Any sample ever received on reader {@code id} that matches (not only new ones). */
    synchronized JsonNode awaitSample(String id, Predicate<JsonNode> data) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        while (true) {
            for (JsonNode e : events) {
                if (e.path("event").asText().equals("sample") && e.path("id").asText().equals(id) && data.test(e.path("data"))) {
                    return e.path("data");
                }
            }
            long left = end - System.currentTimeMillis();
            if (left <= 0) {
                return null;
            }
            wait(Math.min(left, 200));
        }
    }

    synchronized List<JsonNode> samples(String id) {
        return events.stream().filter(e -> e.path("event").asText().equals("sample") && e.path("id").asText().equals(id))
                .map(e -> e.path("data")).toList();
    }

    void endpoint(String op, String id, String topic, String type, String qos) throws IOException, InterruptedException {
        send("{\"op\":\"" + op + "\",\"id\":\"" + id + "\",\"topic\":\"" + topic + "\",\"type\":\"" + type + "\"" + qos + "}");
        assertNotNull(op + " " + id, awaitEvent(e -> e.path("event").asText().equals("ok") && e.path("id").asText().equals(id)));
    }

    /** Waits, in the peer, until {@code id} has matched the bridge's endpoint. */
    void awaitMatched(String id) throws IOException, InterruptedException {
        // the peer gives up first, so a missing match is reported as such rather than as a silent peer
        send("{\"op\":\"await_matched\",\"id\":\"" + id + "\",\"count\":1,\"timeout\":" + (TIMEOUT / 1000 - 10) + "}");
        JsonNode e = awaitEvent(x -> x.path("id").asText().equals(id) && (x.path("event").asText().equals("matched")
                || x.path("event").asText().equals("timeout")));
        assertNotNull("an answer to await_matched " + id, e);
        if (!e.path("event").asText().equals("matched")) {
            throw new AssertionError("the peer's " + id + " never matched the bridge");
        }
    }

    void write(String id, String data) throws IOException, InterruptedException {
        send("{\"op\":\"write\",\"id\":\"" + id + "\",\"data\":" + data + "}");
        assertNotNull("write " + id, awaitEvent(e -> e.path("event").asText().equals("ok") && e.path("op").asText().equals("write")));
    }

    /** Cyclone's CDR of the message ({@code xcdr2}: version 2; {@code appendable}: the types declared appendable), hex. */
    String encode(String type, String data, boolean xcdr2, boolean appendable) throws IOException, InterruptedException {
        send("{\"op\":\"encode\",\"type\":\"" + type + "\",\"data\":" + data + ",\"xcdr2\":" + xcdr2 + ",\"appendable\":" + appendable + "}");
        JsonNode e = awaitEvent(x -> x.path("event").asText().equals("encoded") || x.path("event").asText().equals("error"));
        assertNotNull("the peer encodes a " + type, e);
        if (!e.has("hex")) {
            throw new AssertionError("the peer cannot encode " + data + ": " + e);
        }
        return e.path("hex").asText();
    }

    /** The message Cyclone reads from the payload (hex), or an AssertionError with Cyclone's reason. */
    JsonNode decode(String type, String hex) throws IOException, InterruptedException {
        send("{\"op\":\"decode\",\"type\":\"" + type + "\",\"hex\":\"" + hex + "\"}");
        JsonNode e = awaitEvent(x -> x.path("event").asText().equals("decoded") || x.path("event").asText().equals("error"));
        assertNotNull("the peer decodes a " + type, e);
        if (!e.has("data")) {
            throw new AssertionError("Cyclone cannot decode our " + type + " (" + hex + "): " + e);
        }
        return e.path("data");
    }

    /** Stops the peer at once, as a crashing robot would go. */
    void kill() throws InterruptedException {
        process.destroyForcibly().waitFor();
    }

    @Override
    public void close() throws InterruptedException {
        try {
            send("{\"op\":\"quit\"}");
        } catch (IOException ignored) {
            // already gone
        }
        if (!process.waitFor(5, java.util.concurrent.TimeUnit.SECONDS)) {
            kill();
        }
    }
}
