package org.miron.runtime.skill;

import org.miron.runtime.Contexts;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;
import org.miron.runtime.Connect;
import org.miron.runtime.Json;
import org.miron.runtime.executor.SkillClient;
import org.miron.runtime.executor.SkillHandle;
import org.miron.runtime.executor.SkillRequest;
import org.miron.runtime.executor.SkillResult;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * The BT executor's connection to a SmartSoft skill interface, as the original MIRoN executor
 * spoke to ComponentSkillInterface: push-skill and abort-current-skill requests go through the
 * broker's request path (acked, retried, never blocking the tick), and skill-result messages are
 * read from the skill interface's PUB socket and matched to the pushed skill by id.
 */
public final class ZmqSkillClient implements SkillClient, AutoCloseable {
    private static final Logger LOG = Logger.getLogger(ZmqSkillClient.class.getName());

    private final RequestSender requests;
    private final String resultsEndpoint;
    private final Map<Long, CompletableFuture<SkillResult>> pending = new ConcurrentHashMap<>();
    // Ids start from the clock so that two executor runs never reuse an id the interface may still know.
    private final AtomicLong nextId = new AtomicLong(System.currentTimeMillis() * 1000);
    private final ZContext ctx = Contexts.create();
    private final Thread resultsThread;
    private volatile boolean running = true;
    private volatile long malformed;

    /**
     * @param requestEndpoint  the broker's ROUTER (or the skill interface's REP directly)
     * @param resultsEndpoint  the skill interface's PUB, where skill results appear
     */
    public ZmqSkillClient(String requestEndpoint, String resultsEndpoint, long ackTimeoutMs) {
        this.requests = new RequestSender(requestEndpoint, "executor-skills", ackTimeoutMs, 100, 2000,
                new LoggingListener());
        this.resultsEndpoint = resultsEndpoint;
        this.resultsThread = new Thread(this::readResults, "executor-skill-results");
        this.resultsThread.setDaemon(true);
    }

    public ZmqSkillClient start() {
        resultsThread.start();
        requests.start();
        return this;
    }

    @Override
    public SkillHandle pushSkill(SkillRequest request) {
        long id = nextId.getAndIncrement();
        CompletableFuture<SkillResult> result = new CompletableFuture<>();
        pending.put(id, result);
        result.whenComplete((r, e) -> pending.remove(id));
        requests.submit("push-skill " + id, pushSkillMessage(id, request));
        return SkillHandle.of(result, () -> {
            if (!result.isDone()) {
                requests.submit("abort-current-skill", abortMessage(nextId.getAndIncrement()));
            }
        });
    }

    static ObjectNode pushSkillMessage(long id, SkillRequest request) {
        ObjectNode message = Json.object();
        message.put("id", id);
        message.put("msg-type", "push-skill");
        ObjectNode skill = message.putObject("skill");
        skill.put("name", request.name());
        skill.put("skill-definition-fqn", request.name());
        skill.set("in-attribute", Json.MAPPER.valueToTree(request.inAttributes()));
        skill.putObject("out-attribute");
        return message;
    }

    static ObjectNode abortMessage(long id) {
        ObjectNode message = Json.object();
        message.put("id", id);
        message.put("msg-type", "query");
        message.putObject("query").put("type", "abort-current-skill");
        return message;
    }

    private void readResults() {
        try (ZMQ.Socket sub = ctx.createSocket(SocketType.SUB)) {
            sub.setLinger(0);
            sub.subscribe(new byte[0]);
            Connect.connect(sub, resultsEndpoint);
            sub.setReceiveTimeOut(100);
            while (running) {
                byte[] frame = sub.recv();
                if (frame != null) {
                    onResult(frame);
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("skill results reader stopped: " + e);
            }
        }
    }

    /** Completes the pushed skill a skill-result message names; anything else is counted and dropped. */
    void onResult(byte[] frame) {
        JsonNode message;
        try {
            message = Json.MAPPER.readTree(frame);
        } catch (IOException e) {
            message = null;
        }
        if (message == null || !"skill-result".equals(message.path("msg-type").asText())) {
            malformed++;
            LOG.warning("ignored a message on the skill-result socket that is not a skill-result");
            return;
        }
        CompletableFuture<SkillResult> result = pending.get(message.path("id").asLong(-1));
        if (result == null) {
            return; // a skill of another client, or one this client already gave up
        }
        JsonNode body = message.path("result");
        SkillResult.Outcome outcome;
        try {
            outcome = SkillResult.Outcome.valueOf(body.path("result").asText());
        } catch (IllegalArgumentException e) {
            outcome = SkillResult.Outcome.ERROR;
        }
        Map<String, Object> outputs = new LinkedHashMap<>();
        message.path("outputs").fields().forEachRemaining(f -> outputs.put(f.getKey(), Json.MAPPER.convertValue(f.getValue(), Object.class)));
        Object value = Json.MAPPER.convertValue(body.path("result-value"), Object.class);
        result.complete(new SkillResult(outcome, value, outputs));
    }

    /** Messages on the results socket that were not skill results. */
    public long malformedCount() {
        return malformed;
    }

    @Override
    public void close() {
        running = false;
        requests.close();
        try {
            resultsThread.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        ctx.close();
        pending.values().forEach(f -> f.complete(SkillResult.of(SkillResult.Outcome.ABORT)));
    }

    private static final class LoggingListener implements RequestSender.Listener {
        @Override
        public void sent(String key, ObjectNode message) {
        }

        @Override
        public void acked(String key, ObjectNode message) {
        }

        @Override
        public void retry(String key, ObjectNode message, int attempt, long backoffMs) {
            LOG.warning(key + ": no ack from the skill interface, retry " + attempt + " in " + backoffMs + " ms");
        }
    }
}
