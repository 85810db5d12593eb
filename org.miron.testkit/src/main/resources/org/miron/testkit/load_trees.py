"""Loads BT XML files in the real BehaviorTree.CPP 4 (behaviortreepy): the oracle of the v4 tests.

Usage: python load_trees.py FILE...   Prints one line per file, tab-separated:
"loaded" or "rejected", the file, and the library's error message on one line.

Node IDs that are neither built-ins (of version 4, or of version 3 and dropped since) nor trees of the file are the user's custom nodes: each is registered as a dummy
(action, condition or decorator by its form and child count; a custom control with several
children is loaded as a Sequence, as the bindings cannot register control nodes). The bindings
cannot declare ports either, so a custom node's ports are dropped before loading; built-in nodes,
scripts, pre/post-conditions and subtrees are loaded exactly as written.
"""
import os
import sys
import xml.etree.ElementTree as ET

import behaviortreepy as bt

# BehaviorTreeFactory's built-in registrations in BehaviorTree.CPP 4.8.
BUILTINS = {
    "Fallback", "AsyncFallback", "Sequence", "AsyncSequence", "SequenceWithMemory", "Parallel",
    "ParallelAll", "ReactiveSequence", "ReactiveFallback", "IfThenElse", "WhileDoElse", "Inverter",
    "RetryUntilSuccessful", "KeepRunningUntilFailure", "Repeat", "Timeout", "Delay", "RunOnce",
    "ForceSuccess", "ForceFailure", "AlwaysSuccess", "AlwaysFailure", "Script", "ScriptCondition",
    "SetBlackboard", "Sleep", "UnsetBlackboard", "SubTree", "Precondition", "Switch2", "Switch3",
    "Switch4", "Switch5", "Switch6", "LoopInt", "LoopBool", "LoopDouble", "LoopString",
    "WasEntryUpdated", "SkipUnlessUpdated", "WaitValueUpdate",
}
# Built-ins of BehaviorTree.CPP 3 that version 4 dropped (and FallbackStar, which neither has):
# never registered as dummies, or the oracle would hide exactly the mistakes it must catch.
REMOVED = {
    "SequenceStar", "SubTreePlus", "RetryUntilSuccesful", "BlackboardCheckInt", "BlackboardCheckDouble",
    "BlackboardCheckString", "FallbackStar",
}
EXPLICIT = {"Action", "Condition", "Decorator", "Control"}
STRUCTURE = {"root", "BehaviorTree", "TreeNodesModel", "include"}


def children(element):
    return [c for c in element if isinstance(c.tag, str)]


def prepare(root, factory):
    """Registers the custom nodes of a parsed file and drops their ports; returns the XML text."""
    registered = set()
    trees = {tree.get("ID") for tree in root.iter("BehaviorTree")}
    for tree in root.iter("BehaviorTree"):
        for node in tree.iter():
            if node is tree or not isinstance(node.tag, str):
                continue
            explicit = node.tag in EXPLICIT
            node_id = node.get("ID") if explicit else node.tag
            if node_id is None or node_id in BUILTINS or node_id in REMOVED or node_id in trees:
                continue
            kids = len(children(node))
            if kids > 1:
                node.tag = "Sequence"
                node.attrib.pop("ID", None)
            elif node_id not in registered:
                if kids == 1:
                    factory.register_simple_decorator(node_id, lambda status, n: status)
                elif node.tag == "Condition":
                    factory.register_simple_condition(node_id, lambda n: bt.NodeStatus.SUCCESS)
                else:
                    factory.register_simple_action(node_id, lambda n: bt.NodeStatus.SUCCESS)
                registered.add(node_id)
            for name in list(node.attrib):
                if name not in ("ID", "name") and not name.startswith("_"):
                    del node.attrib[name]
    for model in root.findall("TreeNodesModel"):
        root.remove(model)
    return ET.tostring(root, encoding="unicode")


def inline_includes(root, folder, seen):
    """Replaces each <include path> by the trees of that file (relative to folder), recursively."""
    for include in root.findall("include"):
        root.remove(include)
        path = os.path.normpath(os.path.join(folder, include.get("path", "")))
        if path in seen:
            continue
        seen.add(path)
        included = ET.parse(path).getroot()
        inline_includes(included, os.path.dirname(path), seen)
        for tree in included.findall("BehaviorTree"):
            root.append(tree)


def load(path):
    try:
        root = ET.parse(path).getroot()
        # Included files' custom nodes must be registered too: load one document.
        inline_includes(root, os.path.dirname(os.path.abspath(path)), {os.path.abspath(path)})
        factory = bt.BehaviorTreeFactory()
        text = prepare(root, factory)
        trees = [tree.get("ID") for tree in root.findall("BehaviorTree")]
        if root.get("main_tree_to_execute") is None and len(trees) > 1:
            # A library of trees (included by others, no main tree): each one must instantiate.
            factory.register_behavior_tree_from_text(text)
            for tree_id in trees:
                factory.create_tree(tree_id)
        else:
            factory.create_tree_from_text(text)
        return "loaded", ""
    except Exception as error:  # the library's exceptions carry its message
        return "rejected", " ".join(str(error).split())


def main():
    for path in sys.argv[1:]:
        verdict, message = load(path)
        print(verdict + "\t" + path + "\t" + message, flush=True)


if __name__ == "__main__":
    main()
