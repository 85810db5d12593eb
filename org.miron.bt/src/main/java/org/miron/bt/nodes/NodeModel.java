package org.miron.bt.nodes;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * One built-in node as BehaviorTree.CPP's manifest describes it (registration ID, NodeType,
 * providedPorts) plus what a file checker needs beside: the versions that register it, how many
 * children it takes, other accepted spellings and what the other version writes instead.
 *
 * @param tag the element name, e.g. {@code RetryUntilSuccessful}
 * @param kind its NodeType
 * @param versions the BehaviorTree.CPP versions (3, 4) whose factory registers it
 * @param children how many child elements it takes
 * @param ports its providedPorts, across versions (see {@link PortModel#versions})
 * @param description one sentence for hover and completion
 * @param spellings other element names meaning the same node, each in its own versions
 * @param counterpart what to write in the other version when this one lacks the node, or null
 * @param explicitForm the element names the real node by its ID attribute (Action, Condition,
 *            Control, Decorator: a registered node; SubTree, SubTreePlus: a tree)
 */
public record NodeModel(String tag, NodeKind kind, Set<Integer> versions, Children children, List<PortModel> ports,
        String description, List<Spelling> spellings, Counterpart counterpart, boolean explicitForm) {

    /** Another element name of the node, e.g. BehaviorTree.CPP 3.5's {@code RetryUntilSuccesful}. */
    public record Spelling(String tag, Set<Integer> versions, String note) {
        public Spelling {
            versions = Set.copyOf(versions);
        }
    }

    /**
     * The node to write in the other version; {@code rename}: replacing the element name alone
     * keeps the meaning (SequenceStar ⇄ SequenceWithMemory), else the ports change too
     * (SubTreePlus → SubTree, BlackboardCheckInt → Precondition).
     */
    public record Counterpart(String tag, boolean rename) {
    }

    public NodeModel {
        versions = Set.copyOf(versions);
        ports = List.copyOf(ports);
        spellings = List.copyOf(spellings);
    }

    static NodeModel of(String tag, NodeKind kind, Set<Integer> versions, Children children, String description) {
        return new NodeModel(tag, kind, versions, children, List.of(), description, List.of(), null, false);
    }

    NodeModel ports(PortModel... list) {
        List<PortModel> all = new ArrayList<>(ports);
        all.addAll(List.of(list));
        return new NodeModel(tag, kind, versions, children, all, description, spellings, counterpart, explicitForm);
    }

    NodeModel spelling(String other, int version, String note) {
        List<Spelling> all = new ArrayList<>(spellings);
        all.add(new Spelling(other, Set.of(version), note));
        return new NodeModel(tag, kind, versions, children, ports, description, all, counterpart, explicitForm);
    }

    NodeModel counterpart(String other, boolean rename) {
        return new NodeModel(tag, kind, versions, children, ports, description, spellings,
                new Counterpart(other, rename), explicitForm);
    }

    NodeModel explicit() {
        return new NodeModel(tag, kind, versions, children, ports, description, spellings, counterpart, true);
    }

    public boolean isIn(int version) {
        return versions.contains(version);
    }

    /** Whether {@code element} (this tag or one of its spellings) names this node in {@code version}. */
    public boolean accepts(String element, int version) {
        if (element.equals(tag)) {
            return isIn(version);
        }
        return spellings.stream().anyMatch(s -> s.tag().equals(element) && s.versions().contains(version));
    }

    /** The tag and every spelling. */
    public List<String> tags() {
        List<String> all = new ArrayList<>(List.of(tag));
        spellings.forEach(s -> all.add(s.tag()));
        return all;
    }

    /** The ports of the node in one version, in declaration order. */
    public List<PortModel> ports(int version) {
        return ports.stream().filter(p -> p.isIn(version)).toList();
    }

    /** The port of this name in any version. */
    public Optional<PortModel> port(String name) {
        return ports.stream().filter(p -> p.name().equals(name)).findFirst();
    }

    /** The port of this name in {@code version}. */
    public Optional<PortModel> port(String name, int version) {
        return ports.stream().filter(p -> p.name().equals(name) && p.isIn(version)).findFirst();
    }

    /** The port of this name, for code that writes it (the weaver): an unknown name is a programming error. */
    public PortModel requirePort(String name) {
        return port(name).orElseThrow(() -> new IllegalArgumentException(tag + " has no port " + name));
    }
}
