package org.miron.runtime.skill;

import org.miron.runtime.Bind;
import org.miron.runtime.Contexts;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.SocketWait;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * Stand-in for SmartSoft's ComponentSkillInterface, wire-compatible with it: a REP socket for
 * queries (every request is answered with an empty frame, the ack) and a PUB for skill results.
 * Pushed skills run concurrently, each for its table duration ({@link TableSkills}) or as a
 * simulated world says (org.miron.runtime.sim.LiveWorld); {@code abort-current-skill} ends every
 * running skill with ABORT. One thread owns both sockets and drives the skills' behaviour.
 */
public final class SkillInterfaceMock implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(SkillInterfaceMock.class.getName());
    private static final int KEEP = 10_000; // history and results kept, oldest dropped first

    private final String repEndpoint;
    private final String pubEndpoint;
    private final SkillBehaviour skills;
    private final ZContext ctx = Contexts.create();
    private final List<ParameterChange> history = new ArrayList<>();
    private final Map<String, JsonNode> committed = new LinkedHashMap<>();
    private final List<ObjectNode> results = new ArrayList<>();
    private final List<JsonNode> pushed = new ArrayList<>();
    private ZMQ.Socket rep;
    private ZMQ.Socket pub;
    private Thread thread;
    private volatile boolean active = true;
    private volatile long malformed;

    public SkillInterfaceMock(String repEndpoint, String pubEndpoint, SkillTable table) {
        this(repEndpoint, pubEndpoint, new TableSkills(table));
    }

    public SkillInterfaceMock(String repEndpoint, String pubEndpoint, SkillBehaviour skills) {
        this.repEndpoint = repEndpoint;
        this.pubEndpoint = pubEndpoint;
        this.skills = skills;
    }

    /** Binds on the calling thread so a busy port is reported to the caller. */
    public SkillInterfaceMock start() {
        try {
            rep = ctx.createSocket(SocketType.REP);
            pub = ctx.createSocket(SocketType.PUB);
            rep.setLinger(0);
            pub.setLinger(0);
            Bind.bind(rep, repEndpoint);
            Bind.bind(pub, pubEndpoint);
        } catch (RuntimeException e) {
            ctx.close();
            throw new IllegalStateException("skill interface mock cannot bind: " + e.getMessage(), e);
        }
        thread = new Thread(this::loop, "skill-mock");
        thread.setDaemon(true);
        thread.start();
        LOG.info("skill interface mock: queries " + repEndpoint + ", results " + pubEndpoint);
        return this;
    }

    private void loop() {
        try (SocketWait poller = new SocketWait().add(rep)) {
            skills.start(this::publishResult, System.currentTimeMillis());
            while (active) {
                boolean ready = poller.await(nextTimeout());
                boolean idle = true;
                byte[] request; // the poll only paces the loop; non-blocking reads decide
                while (active && (request = rep.recv(ZMQ.DONTWAIT)) != null) {
                    idle = false;
                    while (rep.hasReceiveMore()) {
                        rep.recv(); // REP strips the envelope; extra body frames are not expected
                    }
                    handle(request);
                    rep.send(new byte[0]); // ack
                }
                skills.advance(System.currentTimeMillis());
                if (ready && idle) {
                    poller.idle(); // a wake-up with nothing to read: see SocketWait
                }
            }
        } catch (RuntimeException e) {
            if (active) {
                LOG.severe("skill interface mock stopped: " + e);
            }
        }
    }

    private long nextTimeout() {
        long now = System.currentTimeMillis();
        long due = skills.nextDue(now);
        return Math.max(1, Math.min(50, due - now));
    }

    private void handle(byte[] request) {
        JsonNode msg;
        try {
            msg = Json.MAPPER.readTree(request);
        } catch (IOException e) {
            msg = null;
        }
        if (msg == null || !msg.isObject()) {
            drop("not a JSON object");
            return;
        }
        long id = msg.path("id").asLong(-1);
        String type = msg.path("msg-type").asText();
        if (type.equals("push-skill")) {
            push(id, msg.path("skill"));
        } else if (type.equals("query")) {
            String q = msg.path("query").path("type").asText();
            if (q.equals("change-parameter")) {
                changeParameter(id, msg.path("query"));
            } else if (q.equals("abort-current-skill")) {
                abortAll();
            } else {
                drop("unknown query type '" + q + "'");
            }
        } else {
            drop("unknown msg-type '" + type + "'");
        }
    }

    private void drop(String why) {
        malformed++;
        LOG.warning("skill interface mock: ignored request: " + why);
    }

    /** Applies the change the SmartSoft way: set the tagged parameter, then COMMIT the set. */
    private void changeParameter(long id, JsonNode q) {
        String repo = q.path("ParameterSetRepository").asText();
        String set = q.path("ParameterSet").asText();
        String param = q.path("Parameter").asText();
        String tag = (repo + "." + set + "." + param).toUpperCase(Locale.ROOT);
        JsonNode values = q.path("values");
        StringBuilder cmd = new StringBuilder(tag);
        values.forEach(v -> cmd.append(' ').append(v.asText()));
        ParameterChange change = new ParameterChange(id, q.path("Component").asText(), repo, set, param, tag,
                values.deepCopy(), List.of(cmd.toString(), "COMMIT"), System.currentTimeMillis());
        synchronized (this) {
            history.add(change);
            if (history.size() > KEEP) {
                history.remove(0);
            }
            committed.put(tag, change.values());
            notifyAll();
        }
        skills.parameter(change, System.currentTimeMillis());
        LOG.info("skill interface mock: " + change.commands());
    }

    private void push(long id, JsonNode skill) {
        synchronized (this) {
            pushed.add(skill.deepCopy());
            notifyAll();
        }
        skills.push(id, skill, System.currentTimeMillis());
    }

    private void abortAll() {
        skills.abortAll(System.currentTimeMillis());
    }

    private void publishResult(long id, String result, JsonNode value, JsonNode outputs) {
        ObjectNode msg = Json.object();
        msg.put("id", id);
        msg.put("msg-type", "skill-result");
        ObjectNode res = msg.putObject("result");
        res.put("result", result);
        res.set("result-value", value);
        msg.set("outputs", outputs);
        pub.send(Json.write(msg));
        synchronized (this) {
            results.add(msg);
            if (results.size() > KEEP) {
                results.remove(0);
            }
            notifyAll();
        }
    }

    /** Every parameter change so far, oldest first. */
    public synchronized List<ParameterChange> history() {
        return List.copyOf(history);
    }

    /** Committed values of a tag such as {@code COMMNAVIGATIONOBJECTS.CDLPARAMETER.TRANSVEL}. */
    public synchronized Optional<JsonNode> committed(String tag) {
        return Optional.ofNullable(committed.get(tag));
    }

    /** The skill part of every push-skill request received so far (name, in-attribute...). */
    public synchronized List<JsonNode> pushed() {
        return List.copyOf(pushed);
    }

    /** Skill results published so far. */
    public synchronized List<ObjectNode> results() {
        return List.copyOf(results);
    }

    /** Waits for a parameter change matching {@code p}; empty on timeout. */
    public synchronized Optional<ParameterChange> awaitChange(Predicate<ParameterChange> p, long timeoutMs)
            throws InterruptedException {
        long end = System.currentTimeMillis() + timeoutMs;
        while (true) {
            for (ParameterChange c : history) {
                if (p.test(c)) {
                    return Optional.of(c);
                }
            }
            long left = end - System.currentTimeMillis();
            if (left <= 0) {
                return Optional.empty();
            }
            wait(left);
        }
    }

    public long malformedRequests() {
        return malformed;
    }

    @Override
    public void close() {
        active = false;
        if (thread != null) {
            try {
                thread.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        skills.close();
        ctx.close();
    }
}
