package org.miron.executor.v4;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.miron.executor.ActionRegistry;
import org.miron.executor.AsyncAction;
import org.miron.executor.AsyncActionNode;
import org.miron.executor.BtBuildException;
import org.miron.executor.BtRuntimeException;
import org.miron.executor.NodeStatus;
import org.miron.executor.Ports;
import org.miron.executor.Tree;
import org.miron.executor.TreeBuilder;
import org.miron.executor.TreeContext;
import org.miron.executor.scripting.ScriptValues;

/** Runs a scenario on our executor with the same scripted leaves and reports it like the oracle. */
final class OurRun {
    private final Scenario scenario;
    private final List<String> trace = new ArrayList<>();

    OurRun(Scenario scenario) {
        this.scenario = scenario;
    }

    List<TickRecord> run(Path scenarioFile) {
        ActionRegistry registry = new ActionRegistry();
        scenario.actionsOrEmpty().forEach((id, statuses) -> {
            Script script = new Script(statuses);
            registry.register(id, spec -> new AsyncActionNode(spec.info(), new ScriptedAction(spec.info().name(), script)));
        });
        scenario.conditionsOrEmpty().forEach((id, statuses) -> {
            Script script = new Script(statuses);
            registry.register(id, spec -> new org.miron.executor.SyncActionNode(spec.info(), ports -> {
                NodeStatus status = script.next();
                trace.add(spec.info().name() + ":tick:" + status);
                return status;
            }));
        });
        List<TickRecord> ticks = new ArrayList<>();
        Tree tree;
        try {
            tree = new TreeBuilder(registry, new TreeContext()).build(scenarioFile.resolveSibling(scenario.tree()));
        } catch (BtBuildException e) {
            ticks.add(new TickRecord(0, null, null, null, e.getMessage()));
            return ticks;
        }
        for (int n = 1; n <= scenario.ticks(); n++) {
            trace.clear();
            NodeStatus status;
            try {
                status = scenario.exactlyOnce() ? tree.tickExactlyOnce() : tree.tickRoot();
            } catch (BtRuntimeException e) {
                ticks.add(new TickRecord(n, null, List.copyOf(trace), null, e.getMessage()));
                return ticks;
            }
            Map<String, String> values = new LinkedHashMap<>();
            for (String key : scenario.blackboardOrEmpty()) {
                values.put(key, tree.blackboard().get(key).map(v -> ScriptValues.toText(ScriptValues.of(v))).orElse(null));
            }
            ticks.add(new TickRecord(n, status.name(), List.copyOf(trace), values, null));
        }
        return ticks;
    }

    /** The statuses of one leaf ID, shared by its nodes: the next on each execution, the last one again at the end. */
    private static final class Script {
        private final List<String> statuses;
        private int next;

        Script(List<String> statuses) {
            this.statuses = statuses;
        }

        NodeStatus next() {
            return NodeStatus.valueOf(statuses.get(Math.min(next++, statuses.size() - 1)));
        }
    }

    private final class ScriptedAction implements AsyncAction {
        private final String name;
        private final Script script;

        ScriptedAction(String name, Script script) {
            this.name = name;
            this.script = script;
        }

        @Override
        public NodeStatus onStart(Ports ports) {
            NodeStatus status = script.next();
            trace.add(name + ":start:" + status);
            return status;
        }

        @Override
        public NodeStatus onRunning(Ports ports) {
            NodeStatus status = script.next();
            trace.add(name + ":run:" + status);
            return status;
        }

        @Override
        public void onHalted() {
            trace.add(name + ":halt");
        }
    }
}
