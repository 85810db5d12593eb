package org.miron.runtime.live;

import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;

import org.miron.executor.ControlNode;
import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.miron.executor.decorators.SubTreeNode;
import org.miron.executor.skills.SkillActionNode;
import org.miron.executor.skills.VariantActionNode;
import org.miron.executor.trace.StatusListener;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Publishes every status change of a running tree on {@code miron.bt.status} (docs/wire-formats.md),
 * so monitors (the live page, an editor's diagram) colour the tree as it runs. A node is named by
 * its index path from the root ("0", "0.2", "0.2.0": the i-th child, a SubTree's called root as its
 * only child), which is how org.miron.diagram numbers the nodes of a tree drawn as it runs, and by
 * its path of names for people.
 */
public final class StatusPublisher implements StatusListener {
    /** Where a message goes: topic and JSON body. */
    public interface Sink {
        void publish(String topic, String body);
    }

    private final Tree tree;
    private final Sink sink;
    private final Map<Node, String> ids = new IdentityHashMap<>();
    private final AtomicLong seq = new AtomicLong();

    public StatusPublisher(Tree tree, Sink sink) {
        this.tree = tree;
        this.sink = sink;
        number(tree.root(), "0");
    }

    private void number(Node node, String id) {
        ids.put(node, id);
        List<Node> children = node.children();
        for (int i = 0; i < children.size(); i++) {
            number(children.get(i), id + "." + i);
        }
    }

    /** The index path of a node of the tree, or null for a node not in it. */
    public String idOf(Node node) {
        return ids.get(node);
    }

    /** Announces the tree being run: {@code miron.bt.tree} {"tree","file","format","nodes","time"}. */
    public String treeMessage(String file) {
        ObjectNode body = Json.MAPPER.createObjectNode();
        body.put("tree", tree.id());
        body.put("file", file);
        body.put("format", tree.formatVersion());
        body.put("nodes", ids.size());
        body.put("time", System.currentTimeMillis());
        return body.toString();
    }

    @Override
    public void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        String id = ids.get(node);
        if (id == null) {
            return;
        }
        ObjectNode body = Json.MAPPER.createObjectNode();
        body.put("tree", tree.id());
        body.put("node", id);
        body.put("path", node.path());
        body.put("kind", kind(node));
        body.put("from", from.name());
        body.put("to", to.name());
        body.put("seq", seq.incrementAndGet());
        body.put("time", timeMillis);
        sink.publish(Topics.BT_STATUS, body.toString());
    }

    /** What the node is at run time: control, decorator, subtree, skill, variant or action. */
    static String kind(Node node) {
        if (node instanceof SubTreeNode) {
            return "subtree";
        }
        if (node instanceof ControlNode) {
            return "control";
        }
        if (node instanceof DecoratorNode) {
            return "decorator";
        }
        if (node instanceof SkillActionNode) {
            return "skill";
        }
        return node instanceof VariantActionNode ? "variant" : "action";
    }
}
