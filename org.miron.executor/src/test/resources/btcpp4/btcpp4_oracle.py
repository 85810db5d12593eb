"""Runs a BehaviorTree.CPP 4 tree in the real library (behaviortreepy) with scripted leaves.

Usage: python btcpp4_oracle.py SCENARIO.json
The scenario names the tree file ("tree", relative to the scenario), the number of ticks, the
leaves and the blackboard keys to report:
  {"tree": "x.xml", "ticks": 5, "mode": "once" | "exactly_once",
   "actions": {"A": ["RUNNING", "SUCCESS"]}, "conditions": {"C": ["FAILURE"]},
   "blackboard": ["x"]}
Every time a leaf is executed (an action's onStart or onRunning, a condition's tick) it returns the
next status of its list; past the end, the last one again. Actions are StatefulActionNodes, so
they can stay RUNNING and are told when halted; conditions are simple conditions.
Prints one JSON line per tick: the root status, the leaf executions in order ("name:start:STATUS",
"name:run:STATUS", "name:halt", "name:tick:STATUS") and the reported blackboard values as the
library prints them (null when unset). A tick that throws prints {"tick": n, "error": ...} and
ends the run.
"""
import json
import os
import sys

import behaviortreepy as bt


def main(path):
    with open(path) as f:
        scenario = json.load(f)
    with open(os.path.join(os.path.dirname(path), scenario["tree"])) as f:
        xml = f.read()
    trace = []
    factory = bt.BehaviorTreeFactory()

    def results(name, statuses):
        state = {"i": 0}

        def next_status():
            i = min(state["i"], len(statuses) - 1)
            state["i"] += 1
            return statuses[i]
        return next_status

    for action_id, statuses in scenario.get("actions", {}).items():
        nxt = results(action_id, statuses)

        def on_start(node, nxt=nxt):
            s = nxt()
            trace.append(f"{node.name()}:start:{s}")
            return getattr(bt.NodeStatus, s)

        def on_running(node, nxt=nxt):
            s = nxt()
            trace.append(f"{node.name()}:run:{s}")
            return getattr(bt.NodeStatus, s)

        def on_halted(node):
            trace.append(f"{node.name()}:halt")

        factory.register_simple_stateful_action(action_id, on_start, on_running, on_halted)

    for condition_id, statuses in scenario.get("conditions", {}).items():
        nxt = results(condition_id, statuses)

        def tick(node, nxt=nxt):
            s = nxt()
            trace.append(f"{node.name()}:tick:{s}")
            return getattr(bt.NodeStatus, s)

        factory.register_simple_condition(condition_id, tick)

    try:
        tree = factory.create_tree_from_text(xml)
    except Exception as e:  # the library refuses the tree
        print(json.dumps({"tick": 0, "error": str(e)}))
        return
    exactly_once = scenario.get("mode", "once") == "exactly_once"
    for n in range(1, scenario["ticks"] + 1):
        trace.clear()
        try:
            status = tree.tick_exactly_once() if exactly_once else tree.tick_once()
        except Exception as e:
            print(json.dumps({"tick": n, "error": str(e), "trace": list(trace)}))
            return
        board = tree.root_blackboard()
        values = {}
        for key in scenario.get("blackboard", []):
            try:
                values[key] = board.get_string(key)
            except Exception:
                values[key] = None
        print(json.dumps({"tick": n, "status": status.name, "trace": list(trace), "blackboard": values}))
        sys.stdout.flush()


if __name__ == "__main__":
    main(sys.argv[1])
