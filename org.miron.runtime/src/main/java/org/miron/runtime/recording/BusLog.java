package org.miron.runtime.recording;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.List;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;

/**
 * The bus beside a recording ({@link Btlog#busLogOf}): every {@code roqme.} and {@code miron.}
 * message of the run (contexts, estimates, observations, decisions and variants, requirement
 * events, the status messages of skill nodes) as JSON Lines, after a first line
 * {@code {"format":"miron-bus-log","version":1}}: {@code {"timeUs","topic","message"}}, timeUs in
 * microseconds since the epoch on the recording's clock (the .btlog's start is on the same
 * clock). The broker's own topics and the other node statuses (the .btlog has them) are left out.
 * Each line is flushed as written: a killed process leaves every line but the one being written.
 */
public final class BusLog implements AutoCloseable {
    public static final String FORMAT = "miron-bus-log";
    public static final int VERSION = 1;
    private static final Logger LOG = Logger.getLogger(BusLog.class.getName());

    private final Writer out;
    private final BusClient bus;
    private boolean failed;

    private BusLog(Path file, String busIn, String busOut) throws IOException {
        out = new BufferedWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8));
        ObjectNode header = Json.MAPPER.createObjectNode().put("format", FORMAT).put("version", VERSION);
        out.write(header + "\n");
        out.flush();
        bus = new BusClient("bus-log", busIn, busOut, List.of("roqme.", "miron."), this::onMessage);
    }

    /** Records the bus of {@code busIn}/{@code busOut} into {@code file} until closed. */
    public static BusLog start(Path file, String busIn, String busOut) throws IOException {
        BusLog log = new BusLog(file, busIn, busOut);
        log.bus.start();
        return log;
    }

    /** Whether a message of this topic is recorded (a bt.status only for a skill node). */
    static boolean recorded(String topic, JsonNode message) {
        if (topic.startsWith(Topics.BROKER_PREFIX)) {
            return false;
        }
        return !topic.equals(Topics.BT_STATUS) || message.path("kind").asText().equals("skill");
    }

    private void onMessage(String topic, byte[] body) {
        JsonNode message;
        try {
            message = Json.MAPPER.readTree(body);
        } catch (IOException e) {
            return; // not ours to judge: the components count malformed inputs
        }
        if (message == null || !message.isObject() || !recorded(topic, message)) {
            return;
        }
        ObjectNode line = Json.MAPPER.createObjectNode();
        line.put("timeUs", ChronoUnit.MICROS.between(Instant.EPOCH, Instant.now()));
        line.put("topic", topic);
        line.set("message", message);
        write(line.toString());
    }

    private synchronized void write(String line) {
        if (failed) {
            return;
        }
        try {
            out.write(line);
            out.write('\n');
            out.flush();
        } catch (IOException e) {
            failed = true;
            LOG.warning("bus log: recording stopped: " + e.getMessage());
        }
    }

    @Override
    public void close() {
        bus.close();
        synchronized (this) {
            try {
                out.close();
            } catch (IOException e) {
                LOG.warning("bus log: " + e.getMessage());
            }
        }
    }
}
