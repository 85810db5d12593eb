package org.miron.dds.config;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;
import org.miron.dds.types.DefinitionException;
import org.miron.dds.types.MessagePackages;
import org.miron.dds.types.TypeRegistry;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import org.miron.dds.config.BridgeConfig.ContextMapping;
import org.miron.dds.config.BridgeConfig.ContextType;
import org.miron.dds.config.BridgeConfig.DecisionMapping;
import org.miron.dds.config.BridgeConfig.EstimateMapping;
import org.miron.dds.config.BridgeConfig.RoqmeTopics;
import org.miron.dds.transport.Qos;
import org.miron.dds.transport.RosNames;
import org.miron.dds.transport.TypeCatalog;

/**
 * Reads and checks a bridge configuration; the first problem is a {@link ConfigException} with its
 * position. The rules are those of docs/dds-bridge.schema.json, plus what a schema cannot say:
 * the message type exists, the field path leads to a value of that type, {@code scale} only on numbers.
 */
public final class ConfigReader {
    /** The default partition of RoQME's topics, as the original RoQME tools use it. */
    public static final String ROQME_PARTITION = "Roqme DDS partition";
    public static final List<String> ROQME_CONTEXT_TOPICS = List.of("RoqmeIntContext", "RoqmeUIntContext",
            "RoqmeDoubleContext", "RoqmeBoolContext", "RoqmeEventContext", "RoqmeEnumContext");
        private static final String IDENT = "[A-Za-z_][A-Za-z0-9_]*";

    private final Located doc;
    private final Path base;
    private final Consumer<String> warnings;
    private TypeCatalog types;
    private TypeRegistry registry = TypeRegistry.NONE;

    private ConfigReader(Located doc, Path base, TypeCatalog types, Consumer<String> warnings) {
        this.doc = doc;
        this.base = base;
        this.types = types;
        this.warnings = warnings;
    }

    /** A configuration whose {@code messages} paths are relative to the working directory. */
    public static BridgeConfig read(String text, TypeCatalog types) throws ConfigException {
        try {
            return read(text, Path.of("bridge.json"), types, w -> { });
        } catch (DefinitionException e) {
            throw new ConfigException(1, 1, "/messages", e.format());
        }
    }

    /**
     * The configuration read from {@code file} ({@code messages} are relative to its folder): a
     * message package that does not load is a {@link DefinitionException} at its line.
     *
     * @param warnings receives a line per loaded type that redefines a shipped one
     */
    public static BridgeConfig read(String text, Path file, TypeCatalog types, Consumer<String> warnings)
            throws ConfigException, DefinitionException {
        Path dir = file.toAbsolutePath().getParent();
        return new ConfigReader(Located.parse(text), dir, types, warnings).configWithPackages();
    }

    private BridgeConfig configWithPackages() throws ConfigException, DefinitionException {
        JsonNode root = doc.root;
        if (root.isObject() && root.has("messages")) {
            List<Path> folders = new ArrayList<>();
            for (JsonNode m : array(root, "", "messages")) {
                String p = "/messages/" + folders.size();
                if (!m.isTextual() || m.asText().isEmpty()) {
                    throw error(p, "a path to a message package (a folder with msg/*.msg or msg/*.idl) is expected");
                }
                Path folder = base.resolve(m.asText()).normalize();
                if (!Files.isDirectory(folder)) {
                    throw error(p, "no such folder: " + folder + " (a message package, relative to the configuration file)");
                }
                folders.add(folder);
            }
            try {
                registry = MessagePackages.load(folders, types::ships, warnings);
            } catch (java.io.IOException e) {
                throw error("/messages", "cannot read a message package: " + e.getMessage());
            }
            types = types.withPackages(registry);
        }
        return config();
    }

    private ConfigException error(String pointer, String reason) {
        int[] pos = doc.position(pointer);
        return new ConfigException(pos[0], pos[1], pointer, reason);
    }

    private BridgeConfig config() throws ConfigException {
        JsonNode root = doc.root;
        if (!root.isObject()) {
            throw error("", "a JSON object is expected");
        }
        keys(root, "", Set.of("$schema", "domain", "name", "interfaces", "messages", "contexts", "decisions", "estimates", "roqme"));
        int domain = integer(root, "", "domain", 0, 0, 232);
        String name = text(root, "", "name", "miron_dds_bridge");
        if (!name.matches(IDENT)) {
            throw error("/name", "a participant name is letters, digits and underscores, got \"" + name + "\"");
        }
        List<InetAddress> interfaces = new ArrayList<>();
        for (JsonNode a : array(root, "", "interfaces")) {
            String p = "/interfaces/" + interfaces.size();
            if (!a.isTextual() || !a.asText().matches("[0-9.]+")) {
                throw error(p, "an IPv4 address is expected, e.g. \"127.0.0.1\"");
            }
            try {
                interfaces.add(InetAddress.getByName(a.asText()));
            } catch (UnknownHostException e) {
                throw error(p, "not an IPv4 address: " + a.asText());
            }
        }
        if (interfaces.isEmpty()) {
            interfaces.add(InetAddress.getLoopbackAddress());
        }
        List<ContextMapping> contexts = new ArrayList<>();
        for (JsonNode c : array(root, "", "contexts")) {
            contexts.add(context(c, "/contexts/" + contexts.size()));
        }
        List<DecisionMapping> decisions = new ArrayList<>();
        for (JsonNode d : array(root, "", "decisions")) {
            decisions.add(decision(d, "/decisions/" + decisions.size()));
        }
        List<EstimateMapping> estimates = new ArrayList<>();
        for (JsonNode e : array(root, "", "estimates")) {
            estimates.add(estimate(e, "/estimates/" + estimates.size()));
        }
        RoqmeTopics roqme = root.has("roqme") ? roqme(root.get("roqme"), "/roqme") : null;
        if (contexts.isEmpty() && decisions.isEmpty() && estimates.isEmpty() && roqme == null) {
            throw error("", "nothing to bridge: give contexts, decisions, estimates or roqme");
        }
        for (int i = 0; i < decisions.size(); i++) {
            for (int j = 0; j < i; j++) {
                String pi = decisions.get(i).parameter();
                if (pi != null && pi.equals(decisions.get(j).parameter())) {
                    throw error("/decisions/" + i + "/parameter", "parameter " + pi + " is already answered by /decisions/" + j);
                }
            }
        }
        return new BridgeConfig(domain, name, List.copyOf(interfaces), contexts, decisions, estimates, roqme, registry);
    }

    private ContextMapping context(JsonNode c, String p) throws ConfigException {
        object(c, p);
        keys(c, p, Set.of("topic", "type", "field", "scale", "context", "namespace", "as", "qos"));
        String topic = rosTopic(c, p);
        String type = required(c, p, "type");
        JsonNode template = types.template(type);
        if (template == null || type.startsWith("Roqme")) {
            throw error(p + "/type", "unknown message type " + type + " (a ROS 2 type as pkg/Name, e.g. sensor_msgs/BatteryState,"
                    + " shipped or of a package in \"messages\")");
        }
        boolean event = c.has("as") && "event".equals(c.get("as").asText());
        String field = text(c, p, "field", event ? "" : "data");
        List<Object> path = field.isEmpty() ? List.of() : FieldPath.parse(field);
        if (path == null) {
            throw error(p + "/field", "not a field path: \"" + field + "\" (names and [index], e.g. header.stamp.sec or cell_voltage[0])");
        }
        JsonNode leaf = FieldPath.resolveTemplate(template, path);
        if (leaf == null || (leaf.isContainerNode() && !field.isEmpty())) {
            throw error(p + "/field", type + " has no value field \"" + field + "\"; its fields: " + FieldPath.describe(template));
        }
        String context = required(c, p, "context");
        if (!context.matches(IDENT)) {
            throw error(p + "/context", "a RoQME context name is an identifier, got \"" + context + "\"");
        }
        ContextType inferred = leaf.isNumber() ? ContextType.NUMBER : leaf.isBoolean() ? ContextType.BOOLEAN : ContextType.ENUM;
        ContextType as = event ? ContextType.EVENT : inferred;
        if (c.has("as") && !event) {
            String a = required(c, p, "as");
            try {
                as = ContextType.valueOf(a.toUpperCase(java.util.Locale.ROOT));
            } catch (IllegalArgumentException e) {
                throw error(p + "/as", "must be number, boolean, enum or event, got \"" + a + "\"");
            }
            if (as != inferred && !(as == ContextType.NUMBER && leaf.isTextual())) {
                throw error(p + "/as", "field \"" + field + "\" of " + type + " holds a " + inferred.json() + ", not a " + as.json());
            }
        }
        double scale = 1;
        if (c.has("scale")) {
            if (!c.get("scale").isNumber()) {
                throw error(p + "/scale", "a number is expected");
            }
            if (as != ContextType.NUMBER) {
                throw error(p + "/scale", "only a number context can be scaled; \"" + field + "\" is fed as " + as.json());
            }
            scale = c.get("scale").asDouble();
        }
        return new ContextMapping(topic, type, field, path, scale, context, text(c, p, "namespace", ""), as,
                qos(c, p, new Qos(false, false, 10)));
    }

    private DecisionMapping decision(JsonNode d, String p) throws ConfigException {
        object(d, p);
        keys(d, p, Set.of("varpoint", "topic", "type", "field", "scale", "set", "parameter", "qos"));
        String vp = required(d, p, "varpoint");
        if (!vp.matches(IDENT)) {
            throw error(p + "/varpoint", "a varpoint name is an identifier, got \"" + vp + "\"");
        }
        String type = text(d, p, "type", "std_msgs/String");
        ObjectNode template = types.template(type);
        if (template == null || type.startsWith("Roqme")) {
            throw error(p + "/type", "unknown message type " + type + " (a ROS 2 type as pkg/Name, shipped or of a package in \"messages\")");
        }
        String field = text(d, p, "field", "data");
        List<Object> path = FieldPath.parse(field);
        if (path == null) {
            throw error(p + "/field", "not a field path: \"" + field + "\" (names and [index], e.g. speed_limit or header.frame_id)");
        }
        JsonNode leaf = FieldPath.resolveTemplate(template, path);
        if (leaf == null || leaf.isContainerNode()) {
            throw error(p + (d.has("field") ? "/field" : ""), type + " has no value field \"" + field + "\"; its fields: "
                    + FieldPath.describe(template));
        }
        if (!FieldPath.set(template.deepCopy(), path, leaf)) {
            throw error(p + "/field", "\"" + field + "\" of " + type + " is an element of an array that has none by default;"
                    + " a decision goes to a field or an element of a fixed array");
        }
        double scale = 1;
        if (d.has("scale")) {
            if (!d.get("scale").isNumber() || !Double.isFinite(d.get("scale").asDouble())) {
                throw error(p + "/scale", "a number is expected");
            }
            if (!leaf.isNumber()) {
                throw error(p + "/scale", "only a number field can be scaled; \"" + field + "\" of " + type + " is not one");
            }
            scale = d.get("scale").asDouble();
        }
        ObjectNode base = template.deepCopy();
        if (d.has("set")) {
            JsonNode set = d.get("set");
            object(set, p + "/set");
            for (Iterator<String> it = set.fieldNames(); it.hasNext();) {
                String k = it.next();
                String sp = p + "/set/" + k.replace("~", "~0").replace("/", "~1");
                List<Object> kp = FieldPath.parse(k);
                JsonNode target = kp == null ? null : FieldPath.resolveTemplate(template, kp);
                if (target == null || target.isObject() || kp.equals(path)) {
                    throw error(sp, kp != null && kp.equals(path) ? "\"" + k + "\" is the field the decision goes to"
                            : type + " has no value field \"" + k + "\"; its fields: " + FieldPath.describe(template));
                }
                JsonNode v = set.get(k);
                if (target.isNumber() != v.isNumber() || target.isBoolean() != v.isBoolean() || target.isTextual() != v.isTextual()
                        || target.isArray() != v.isArray() || target.isIntegralNumber() && !v.isIntegralNumber()) {
                    throw error(sp, "\"" + k + "\" of " + type + " holds " + kind(target) + ", not " + v);
                }
                if (!FieldPath.set(base, kp, v)) {
                    throw error(sp, "\"" + k + "\" of " + type + " cannot be set (an element past the end of an array)");
                }
            }
        }
        String parameter = null;
        if (d.has("parameter")) {
            parameter = text(d, p, "parameter", null);
            if (!parameter.matches(IDENT)) {
                throw error(p + "/parameter", "the arch-bound parameter's name (as in the model's in arch { parameter ... }), got \"" + parameter + "\"");
            }
            if (!leaf.isNumber() && !leaf.isBoolean()) {
                throw error(p + "/parameter", "a parameter's value is a number or boolean; \"" + field + "\" of " + type + " holds " + kind(leaf));
            }
        }
        JsonNode stamp = FieldPath.resolveTemplate(template, List.of("header", "stamp"));
        boolean stamped = stamp != null && stamp.has("sec") && stamp.has("nanosec") && !"header".equals(path.get(0));
        return new DecisionMapping(vp, rosTopic(d, p), type, qos(d, p, Qos.LATCHED), field, path, leaf, scale, base, stamped, parameter);
    }

    private static String kind(JsonNode v) {
        return v.isIntegralNumber() ? "an integer" : v.isNumber() ? "a number" : v.isBoolean() ? "a boolean" : v.isArray() ? "an array" : "a string";
    }

    private EstimateMapping estimate(JsonNode e, String p) throws ConfigException {
        object(e, p);
        keys(e, p, Set.of("metric", "namespace", "topic", "qos"));
        String metric = required(e, p, "metric");
        if (!metric.matches(IDENT)) {
            throw error(p + "/metric", "a metric name is an identifier, got \"" + metric + "\"");
        }
        return new EstimateMapping(metric, text(e, p, "namespace", ""), rosTopic(e, p), qos(e, p, Qos.LATCHED));
    }

    private RoqmeTopics roqme(JsonNode r, String p) throws ConfigException {
        object(r, p);
        keys(r, p, Set.of("partition", "namespace", "contexts", "estimates", "qos", "keyed"));
        List<String> topics = new ArrayList<>();
        if (!r.has("contexts") || r.get("contexts").isBoolean()) {
            if (!r.has("contexts") || r.get("contexts").asBoolean()) {
                topics.addAll(ROQME_CONTEXT_TOPICS);
            }
        } else {
            for (JsonNode t : array(r, p, "contexts")) {
                String tp = p + "/contexts/" + topics.size();
                if (!ROQME_CONTEXT_TOPICS.contains(t.asText())) {
                    throw error(tp, "not a RoQME context topic: " + t + " (one of " + String.join(", ", ROQME_CONTEXT_TOPICS) + ")");
                }
                topics.add(t.asText());
            }
        }
        String estimates = text(r, p, "estimates", "out");
        if (!Set.of("in", "out", "none").contains(estimates)) {
            throw error(p + "/estimates", "must be \"out\" (roqme.estimate to RoqmeEstimate), \"in\" (RoqmeEstimate to roqme.estimate) or \"none\"");
        }
        return new RoqmeTopics(text(r, p, "partition", ROQME_PARTITION), text(r, p, "namespace", ""), List.copyOf(topics), estimates,
                qos(r, p, new Qos(true, false, 100)), bool(r, p, "keyed", true));
    }

    private Qos qos(JsonNode parent, String p, Qos dflt) throws ConfigException {
        if (!parent.has("qos")) {
            return dflt;
        }
        JsonNode q = parent.get("qos");
        String qp = p + "/qos";
        object(q, qp);
        keys(q, qp, Set.of("reliability", "durability", "depth"));
        String rel = text(q, qp, "reliability", dflt.reliable() ? "reliable" : "best_effort");
        if (!rel.equals("reliable") && !rel.equals("best_effort")) {
            throw error(qp + "/reliability", "must be reliable or best_effort, got \"" + rel + "\"");
        }
        String dur = text(q, qp, "durability", dflt.transientLocal() ? "transient_local" : "volatile");
        if (!dur.equals("volatile") && !dur.equals("transient_local")) {
            throw error(qp + "/durability", "must be volatile or transient_local, got \"" + dur + "\"");
        }
        return new Qos(rel.equals("reliable"), dur.equals("transient_local"), integer(q, qp, "depth", dflt.depth(), 1, 10_000));
    }

    private String rosTopic(JsonNode o, String p) throws ConfigException {
        String t = required(o, p, "topic");
        if (t.startsWith("rt/")) {
            throw error(p + "/topic", "give the ROS 2 name without rt/ (the bridge adds it): \"" + t.substring(3) + "\"");
        }
        if (!RosNames.validTopic(t)) {
            throw error(p + "/topic", "not a ROS 2 topic name: \"" + t + "\" (tokens of letters, digits and _ separated by /)");
        }
        return t;
    }

    private void object(JsonNode n, String p) throws ConfigException {
        if (!n.isObject()) {
            throw error(p, "a JSON object is expected");
        }
    }

    private void keys(JsonNode o, String p, Set<String> allowed) throws ConfigException {
        for (Iterator<String> it = o.fieldNames(); it.hasNext();) {
            String k = it.next();
            if (!allowed.contains(k)) {
                throw error(p + "/" + k, "unknown key \"" + k + "\" (allowed: " + String.join(", ", new java.util.TreeSet<>(allowed)) + ")");
            }
        }
    }

    private String required(JsonNode o, String p, String key) throws ConfigException {
        if (!o.has(key)) {
            throw error(p, "missing \"" + key + "\"");
        }
        return text(o, p, key, null);
    }

    private String text(JsonNode o, String p, String key, String dflt) throws ConfigException {
        if (!o.has(key)) {
            return dflt;
        }
        JsonNode v = o.get(key);
        if (!v.isTextual() || v.asText().isEmpty()) {
            throw error(p + "/" + key, "a non-empty string is expected");
        }
        return v.asText();
    }

    private boolean bool(JsonNode o, String p, String key, boolean dflt) throws ConfigException {
        if (!o.has(key)) {
            return dflt;
        }
        if (!o.get(key).isBoolean()) {
            throw error(p + "/" + key, "true or false is expected, got " + o.get(key));
        }
        return o.get(key).asBoolean();
    }

    private int integer(JsonNode o, String p, String key, int dflt, int min, int max) throws ConfigException {
        if (!o.has(key)) {
            return dflt;
        }
        JsonNode v = o.get(key);
        if (!v.isIntegralNumber() || v.asLong() < min || v.asLong() > max) {
            throw error(p + "/" + key, "an integer from " + min + " to " + max + " is expected, got " + v);
        }
        return v.asInt();
    }

    private Iterable<JsonNode> array(JsonNode o, String p, String key) throws ConfigException {
        if (!o.has(key)) {
            return List.of();
        }
        if (!o.get(key).isArray()) {
            throw error(p + "/" + key, "an array is expected");
        }
        return o.get(key);
    }
}
