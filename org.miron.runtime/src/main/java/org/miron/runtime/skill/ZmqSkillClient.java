package org.miron.runtime.skill;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;
import org.miron.executor.skills.SkillClient;
import org.miron.executor.skills.SkillHandle;
import org.miron.executor.skills.SkillRequest;
import org.miron.executor.skills.SkillResult;
import org.miron.runtime.Connect;
import org.miron.runtime.Contexts;
import org.miron.runtime.Json;
import org.miron.runtime.LinkMonitor;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * The BT executor's connection to a SmartSoft skill interface, as the original MIRoN executor
 * spoke to ComponentSkillInterface: push-skill and abort-current-skill requests go through the
 * broker's request path (acked, retried, never blocking the tick), and skill-result messages are
 * read from the skill interface's PUB socket and matched to the pushed skill by id.
 *
 * <p>A result can be lost: the skill interface dies, or is restarted, while the skill runs. So a
 * pushed skill ends with ERROR (its node FAILS and the tree decides, e.g. a RetryUntilSuccessful
 * pushes it again) when
 * <ul>
 * <li>its {@link SkillDeadlines deadline} passes (an abort-current-skill is sent too, so the robot
 *     does not keep doing what the tree gave up), or</li>
 * <li>the results connection drops (the interface died or restarted): a socket monitor on the
 *     results SUB reports the disconnection of an established (handshaken) link, and a PUB keeps
 *     no results for a subscriber that is away, so no pending result can come any more. Every
 *     pending skill fails and its request, if not yet acknowledged, is withdrawn.</li>
 * </ul>
 * The skill is not pushed again automatically: it may have half run (a GoTo), so whether to
 * repeat a physical action is the tree's decision. For the same reason a push is sent only while
 * the results link is up (held back until then): otherwise a restarted interface, reached first
 * through the broker, could publish a short skill's result before our SUB has reconnected.
 */
public final class ZmqSkillClient implements SkillClient, AutoCloseable {
    private static final Logger LOG = Logger.getLogger(ZmqSkillClient.class.getName());

    private final RequestSender requests;
    private final String resultsEndpoint;
    /** A pushed skill waiting for its result. */
    private static final class Pending {
        final String skill;
        final CompletableFuture<SkillResult> result = new CompletableFuture<>();
        final long deadlineNanos;
        volatile boolean acked;
        volatile boolean sent;
        ObjectNode message;

        Pending(String skill, long deadlineMs) {
            this.skill = skill;
            this.deadlineNanos = System.nanoTime() + deadlineMs * 1_000_000L;
        }
    }

    private final Map<Long, Pending> pending = new ConcurrentHashMap<>();
    private final Queue<Long> held = new ConcurrentLinkedQueue<>(); // pushes not sent yet
    private final SkillDeadlines deadlines;
    // Ids start from the clock so that two executor runs never reuse an id the interface may still know.
    private final AtomicLong nextId = new AtomicLong(System.currentTimeMillis() * 1000);
    private final ZContext ctx = Contexts.create();
    private final Thread resultsThread;
    private volatile boolean running = true;
    private volatile long malformed;
    private volatile long failedByFault;

    /**
     * @param requestEndpoint  the broker's ROUTER (or the skill interface's REP directly)
     * @param resultsEndpoint  the skill interface's PUB, where skill results appear
     */
    public ZmqSkillClient(String requestEndpoint, String resultsEndpoint, long ackTimeoutMs) {
        this(requestEndpoint, resultsEndpoint, ackTimeoutMs, SkillDeadlines.defaults());
    }

    public ZmqSkillClient(String requestEndpoint, String resultsEndpoint, long ackTimeoutMs, SkillDeadlines deadlines) {
        this.deadlines = deadlines;
        this.requests = new RequestSender(requestEndpoint, "executor-skills", ackTimeoutMs, 100, 2000,
                new AckListener());
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
        Pending p = new Pending(request.name(), deadlines.forSkill(request.name()));
        CompletableFuture<SkillResult> result = p.result;
        pending.put(id, p);
        result.whenComplete((r, e) -> pending.remove(id));
        p.message = pushSkillMessage(id, request);
        held.add(id); // sent by the results thread once the results link is up
        return SkillHandle.of(result, () -> {
            if (result.isDone()) {
                return;
            }
            if (!p.sent) {
                result.complete(SkillResult.of(SkillResult.Outcome.ABORT)); // never sent: drops it from the held ones
            } else {
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
        try (ZMQ.Socket sub = ctx.createSocket(SocketType.SUB); LinkMonitor link = new LinkMonitor(ctx, sub)) {
            sub.setLinger(0);
            sub.subscribe(new byte[0]);
            Connect.connect(sub, resultsEndpoint);
            sub.setReceiveTimeOut(100);
            while (running) {
                byte[] frame = sub.recv();
                if (frame != null) {
                    onResult(frame);
                }
                if (link.dropped()) {
                    failPending("the skill interface went away (results connection lost); its result is lost");
                }
                if (link.isUp()) {
                    sendHeld();
                }
                expireDeadlines();
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("skill results reader stopped: " + e);
            }
        }
    }

    private void failPending(String why) {
        pending.forEach((id, p) -> {
            fail(p, why);
            requests.cancel(pushKey(id));
        });
    }

    private void sendHeld() {
        Long id;
        while ((id = held.poll()) != null) {
            Pending p = pending.get(id);
            if (p != null) { // not failed or aborted meanwhile
                p.sent = true;
                requests.submit(pushKey(id), p.message);
            }
        }
    }

    private static String pushKey(long id) {
        return "push-skill " + id;
    }

    private void expireDeadlines() {
        long now = System.nanoTime();
        for (Pending p : pending.values()) {
            if (now - p.deadlineNanos >= 0 && fail(p, "no result within " + deadlines.forSkill(p.skill) + " ms")) {
                requests.submit("abort-current-skill", abortMessage(nextId.getAndIncrement()));
            }
        }
    }

    private boolean fail(Pending p, String why) {
        boolean failed = p.result.complete(new SkillResult(SkillResult.Outcome.ERROR, why, Map.of()));
        if (failed) {
            failedByFault++;
            LOG.warning("skill " + p.skill + " failed: " + why);
        }
        return failed;
    }

    /** Pushed skills ended with ERROR because their deadline passed or the skill interface went away. */
    public long failedByFault() {
        return failedByFault;
    }

    /** Pushed skills acknowledged by the skill interface and still waiting for their result. */
    public long acknowledgedRunning() {
        return pending.values().stream().filter(p -> p.acked && !p.result.isDone()).count();
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
        Pending p = pending.get(message.path("id").asLong(-1));
        CompletableFuture<SkillResult> result = p == null ? null : p.result;
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
        pending.values().forEach(p -> p.result.complete(SkillResult.of(SkillResult.Outcome.ABORT)));
    }

    /** Marks acknowledged pushes (their result is now the interface's to send) and logs retries. */
    private final class AckListener implements RequestSender.Listener {
        @Override
        public void sent(String key, ObjectNode message) {
        }

        @Override
        public void acked(String key, ObjectNode message) {
            Pending p = pending.get(message.path("id").asLong(-1));
            if (p != null && "push-skill".equals(message.path("msg-type").asText())) {
                p.acked = true;
            }
        }

        @Override
        public void retry(String key, ObjectNode message, int attempt, long backoffMs) {
            LOG.warning(key + ": no ack from the skill interface, retry " + attempt + " in " + backoffMs + " ms");
        }
    }
}
