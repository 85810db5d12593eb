package org.miron.bt.nodes;

import java.util.Set;
import java.util.regex.Pattern;

/**
 * The C++ type of a built-in port, as far as a literal written in the XML must convert to it
 * (BehaviorTree.CPP's convertFromString); ANY is an untyped port or one whose value is a
 * blackboard entry of any type.
 */
public enum PortType {
    INT("int"), UNSIGNED("unsigned"), DOUBLE("double"), BOOL("bool"), STRING("std::string"),
    STATUS("BT::NodeStatus"), ANY(null);

    /** convertFromString&lt;bool&gt; accepts exactly these. */
    public static final Set<String> BOOLEANS = Set.of("true", "True", "TRUE", "false", "False", "FALSE", "1", "0");
    /** convertFromString&lt;NodeStatus&gt; accepts exactly these. */
    public static final Set<String> STATUSES = Set.of("IDLE", "RUNNING", "SUCCESS", "FAILURE", "SKIPPED");

    private static final Pattern INTEGER = Pattern.compile("[-+]?\\d+");
    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");

    private final String cppName;

    PortType(String cppName) {
        this.cppName = cppName;
    }

    /** The type as BehaviorTree.CPP 4 writes it in a TreeNodesModel's {@code type} attribute; null for ANY. */
    public String cppName() {
        return cppName;
    }

    /** Whether this type reads an integer (INT or UNSIGNED). */
    public boolean isInteger() {
        return this == INT || this == UNSIGNED;
    }

    /** Whether a literal (not a blackboard pointer) converts to this type. */
    public boolean accepts(String literal) {
        String value = literal.trim();
        switch (this) {
        case INT:
            return INTEGER.matcher(value).matches() && fitsInt(value);
        case UNSIGNED:
            return INTEGER.matcher(value).matches() && fitsInt(value) && Integer.parseInt(value) >= 0;
        case DOUBLE:
            return NUMBER.matcher(value).matches();
        case BOOL:
            return BOOLEANS.contains(value);
        case STATUS:
            return STATUSES.contains(value);
        default:
            return true;
        }
    }

    private static boolean fitsInt(String value) {
        try {
            Integer.parseInt(value);
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }
}
