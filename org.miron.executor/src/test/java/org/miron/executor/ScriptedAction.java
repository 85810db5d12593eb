package org.miron.executor;

/**
 * A test action whose result the test sets before each tick, counting what the tree did to it.
 * Every node with the same ID shares one script, so a test can drive it tick by tick.
 */
final class ScriptedAction implements AsyncAction {
    NodeStatus next = NodeStatus.SUCCESS;
    int starts;
    int ticks;
    int halts;

    static ScriptedAction register(ActionRegistry registry, String id) {
        ScriptedAction script = new ScriptedAction();
        registry.register(id, spec -> new AsyncActionNode(spec.info(), script));
        return script;
    }

    ScriptedAction returns(NodeStatus status) {
        next = status;
        return this;
    }

    @Override
    public NodeStatus onStart(Ports ports) {
        starts++;
        ticks++;
        return next;
    }

    @Override
    public NodeStatus onRunning(Ports ports) {
        ticks++;
        return next;
    }

    @Override
    public void onHalted() {
        halts++;
    }
}
