package org.miron.bt.validation;

import java.util.List;
import java.util.Map;
import java.util.Set;

import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.PortType;

/**
 * What changed between BehaviorTree.CPP 3 and 4, as data shared by the validator and the converter;
 * which built-ins each version has comes from the catalogue (org.miron.bt.nodes).
 */
public final class BtVersions {
    private BtVersions() {
    }

    /** The pre/post-condition attributes BT.CPP 4 evaluates as scripts on any node. */
    public static final List<String> SCRIPT_DIRECTIVES = List.of("_successIf", "_failureIf", "_skipIf", "_while",
            "_onSuccess", "_onFailure", "_onHalted", "_post");

    /** The other attributes starting with '_' that BT.CPP 4 or Groot2 give a meaning: no mistyped pre/post-condition. */
    public static final Set<String> OTHER_UNDERSCORE_ATTRIBUTES = Set.of("_autoremap", "_description", "_uid", "_fullpath");

    /** Built-in tags BT.CPP 4 added, with the version-3 tag that means the same, or "" when none does (from the catalogue). */
    public static final Map<String, String> V4_ONLY_TAGS = NodeCatalogue.onlyIn(NodeCatalogue.V4);

    /** Tags BT.CPP 4 does not register, with what to write there instead (from the catalogue). */
    public static final Map<String, String> V3_ONLY_TAGS = NodeCatalogue.onlyIn(NodeCatalogue.V3);

    /** Parallel's ports: version 3 name to version 4 name. */
    public static final Map<String, String> PARALLEL_PORTS = Map.of(
            "success_threshold", "success_count", "failure_threshold", "failure_count");

    /** BT.CPP's convertFromString&lt;bool&gt; accepts exactly these. */
    public static final Set<String> BOOLEANS = PortType.BOOLEANS;
}
