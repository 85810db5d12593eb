package org.miron.cli.demo;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.miron.runtime.Json;
import org.miron.runtime.bus.BusClient;

/**
 * Records what happens on the bus during a run, RoQME inputs and MIRoN outputs, with the time each
 * message was seen, for the console and the report.
 */
public final class BusRecorder implements AutoCloseable {
    /** One message seen on the bus, {@code at} ms after the recorder started. */
    public static final class Event {
        private final long at;
        private final String topic;
        private final JsonNode body;

        public Event(long at, String topic, JsonNode body) {
            this.at = at;
            this.topic = topic;
            this.body = body;
        }

        public long at() {
            return at;
        }

        public String topic() {
            return topic;
        }

        public JsonNode body() {
            return body;
        }
    }

    private final long start = System.currentTimeMillis();
    private final List<Event> events = new ArrayList<>();
    private final Consumer<Event> listener;
    private final BusClient bus;

    public BusRecorder(String busIn, String busOut, Consumer<Event> listener) {
        this.listener = listener;
        this.bus = new BusClient("recorder", busIn, busOut, List.of("roqme.", "miron."), this::onMessage);
    }

    public BusRecorder start() {
        bus.start();
        return this;
    }

    private void onMessage(String topic, byte[] body) {
        JsonNode json;
        try {
            json = Json.MAPPER.readTree(body);
        } catch (IOException e) {
            return; // not ours to judge: the engine counts malformed inputs
        }
        if (json == null || !json.isObject()) {
            return;
        }
        Event event = new Event(System.currentTimeMillis() - start, topic, json);
        synchronized (this) {
            events.add(event);
        }
        listener.accept(event);
    }

    /** Milliseconds since the recorder started. */
    public long elapsed() {
        return System.currentTimeMillis() - start;
    }

    public synchronized List<Event> events() {
        return List.copyOf(events);
    }

    @Override
    public void close() {
        bus.close();
    }
}
