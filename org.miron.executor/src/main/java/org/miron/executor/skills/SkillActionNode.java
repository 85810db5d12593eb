package org.miron.executor.skills;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;
import org.miron.executor.Conversions;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.Ports;

/**
 * An action carried out by the skill interface: the first tick pushes the skill named like the
 * action ID with the node's attributes as in-attributes, later ticks are RUNNING until its result
 * arrives (SUCCESS → SUCCESS, ERROR/ABORT → FAILURE); halting it aborts the skill. Out-attributes
 * are written to the node's blackboard ports of the same name. A port pointing at a blackboard key
 * without a value is never sent: unless the file declares it as an output_port of the action (the
 * skill writes it), the node fails without pushing the skill and reports one line saying which
 * port, which key and where its value was expected to come from (BehaviorTree.CPP's getInput
 * fails the same way).
 */
public class SkillActionNode extends Node {
    private final String skill;
    private final SkillClient client;
    private final Set<String> outputPorts;
    private SkillHandle running;
    private volatile String lastError;

    public SkillActionNode(NodeInfo info, String skill, SkillClient client) {
        this(info, skill, client, Set.of());
    }

    /** @param outputPorts the ports declared as output_port: written from the result, never sent */
    public SkillActionNode(NodeInfo info, String skill, SkillClient client, Set<String> outputPorts) {
        super(info);
        this.skill = skill;
        this.client = client;
        this.outputPorts = Set.copyOf(outputPorts);
    }

    @Override
    protected NodeStatus tick() {
        if (status() != NodeStatus.RUNNING || running == null) {
            Optional<String> unset = unsetInput();
            if (unset.isPresent()) {
                lastError = unset.get();
                context().reportProblem(lastError);
                return NodeStatus.FAILURE;
            }
            try {
                running = client.pushSkill(new SkillRequest(skill, inAttributes()));
            } catch (RuntimeException e) {
                // the skill interface is unreachable or refused: the action fails, the tree decides
                lastError = "push-skill " + skill + " failed: " + e;
                return NodeStatus.FAILURE;
            }
        }
        if (!running.result().isDone()) {
            return NodeStatus.RUNNING;
        }
        SkillHandle done = running;
        running = null;
        return finish(done);
    }

    /** The message of the first input port whose blackboard key has no value, if any. */
    private Optional<String> unsetInput() {
        return ports().attributes().keySet().stream()
                .filter(port -> isSent(port) && ports().unsetKey(port).isPresent())
                .findFirst()
                .map(port -> path() + ": skill " + skill + " not pushed: " + ports().problem(port));
    }

    private boolean isSent(String port) {
        return !port.equals("ID") && !port.equals("name") && !outputPorts.contains(port);
    }

    /** Ports by value, numbers where they read as one; declared outputs still unset are skipped. */
    Map<String, Object> inAttributes() {
        Map<String, Object> in = new LinkedHashMap<>();
        ports().attributes().forEach((port, written) -> {
            if (port.equals("ID") || port.equals("name") || outputPorts.contains(port) && ports().unsetKey(port).isPresent()) {
                return;
            }
            if (Ports.blackboardKey(port, written).isPresent()) {
                // literals a SubTreePlus wrote (x_input="-9.33") are strings: send numbers as numbers
                ports().get(port).ifPresent(value -> in.put(port, value instanceof String text ? Conversions.toScalar(text) : value));
            } else {
                in.put(port, Conversions.toScalar(written));
            }
        });
        return in;
    }

    private NodeStatus finish(SkillHandle done) {
        SkillResult result;
        try {
            result = done.result().get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            lastError = "interrupted";
            return NodeStatus.FAILURE;
        } catch (ExecutionException | CancellationException | CompletionException e) {
            lastError = String.valueOf(e.getCause() != null ? e.getCause() : e);
            return NodeStatus.FAILURE;
        }
        result.outputs().forEach((port, value) -> {
            if (Ports.blackboardKey(port, ports().raw(port)).isPresent()) {
                ports().set(port, value);
            }
        });
        lastError = result.outcome() == SkillResult.Outcome.SUCCESS ? null : skill + " ended with " + result.outcome();
        return result.outcome() == SkillResult.Outcome.SUCCESS ? NodeStatus.SUCCESS : NodeStatus.FAILURE;
    }

    @Override
    protected void onHalt() {
        if (running != null) {
            SkillHandle aborted = running;
            running = null;
            aborted.abort();
        }
    }

    /** Why the last run failed, if it did. */
    public Optional<String> lastError() {
        return Optional.ofNullable(lastError);
    }
}
