package org.miron.dds;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.logging.Logger;
import org.miron.runtime.Bind;
import org.miron.runtime.Contexts;
import org.miron.runtime.Json;
import org.miron.runtime.SocketWait;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * The bridge in the SmartSoft skill interface's place (its REP endpoint, 5557 by default, behind
 * the broker's request path): a change-parameter query for a parameter a decision mapping names is
 * written to its ROS 2 topic and then acknowledged, so the engine's parameter sender stops retrying
 * as it does when the skill interface commits a change. Every query is answered (REP must, and the
 * skill interface acknowledges whatever it receives); those the bridge cannot apply are counted as
 * {@code queriesIgnored} and logged.
 */
final class ParameterAnswers implements AutoCloseable {
    /** Applies one change: true once written, false when no mapping names the parameter. */
    interface Apply {
        boolean change(String parameter, JsonNode value);
    }

    private static final Logger LOG = Logger.getLogger(ParameterAnswers.class.getName());
    private final ZContext ctx = Contexts.create();
    private final ZMQ.Socket rep;
    private final Apply apply;
    private final BridgeCounters counters;
    private final Thread thread;
    private volatile boolean running = true;

    ParameterAnswers(String endpoint, Apply apply, BridgeCounters counters) {
        this.apply = apply;
        this.counters = counters;
        try {
            rep = ctx.createSocket(SocketType.REP);
            rep.setLinger(0);
            Bind.bind(rep, endpoint);
        } catch (RuntimeException e) {
            ctx.close();
            throw new IllegalStateException("cannot answer change-parameter queries on " + endpoint + ": " + e.getMessage()
                    + " (is a skill interface already there?)", e);
        }
        thread = new Thread(this::loop, "dds-bridge-parameters");
        thread.setDaemon(true);
        thread.start();
        LOG.info("dds-bridge: answering change-parameter queries on " + endpoint);
    }

    private void loop() {
        try (SocketWait poller = new SocketWait().add(rep)) {
            while (running) {
                boolean ready = poller.await(100);
                boolean idle = true;
                byte[] request;
                while (running && (request = rep.recv(ZMQ.DONTWAIT)) != null) {
                    idle = false;
                    while (rep.hasReceiveMore()) {
                        rep.recv();
                    }
                    try {
                        handle(request);
                    } catch (RuntimeException e) { // a bug of ours must not leave the engine unanswered
                        ignored("cannot apply: " + e);
                    }
                    rep.send(new byte[0]); // the ack, after the write
                }
                if (ready && idle) {
                    poller.idle();
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("dds-bridge: change-parameter answers stopped: " + e);
            }
        }
    }

    private void handle(byte[] request) {
        JsonNode msg;
        try {
            msg = Json.MAPPER.readTree(request);
        } catch (IOException e) {
            msg = null;
        }
        JsonNode q = msg == null ? null : msg.path("query");
        if (q == null || !msg.path("msg-type").asText().equals("query") || !q.path("type").asText().equals("change-parameter")) {
            ignored("not a change-parameter query: " + (msg == null ? "not JSON" : msg.path("msg-type").asText() + " " + q.path("type").asText()));
            return;
        }
        String parameter = q.path("Parameter").asText();
        JsonNode value = q.path("values").path("1");
        if (!value.isNumber() && !value.isBoolean()) {
            ignored("change-parameter " + parameter + " has no number or boolean in values.1");
        } else if (apply.change(parameter, value)) {
            counters.add("parametersIn");
        } else {
            ignored("no decision mapping names parameter " + parameter);
        }
    }

    private void ignored(String why) {
        counters.add("queriesIgnored");
        counters.error("queriesIgnored", why);
        LOG.warning("dds-bridge: acknowledged, not applied: " + why);
    }

    @Override
    public void close() {
        running = false;
        try {
            thread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        ctx.close();
    }
}
