package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The message definitions the bridge can encode itself: those of the loaded packages, and its own
 * copies of the few shipped types other definitions nest ({@code builtin_interfaces/Time},
 * {@code std_msgs/Header} ..., written from their field lists under {@code shipped/}). Every nested
 * name is resolved when the registry is built, so an unknown type is a start-up error at its line.
 */
public final class TypeRegistry {
    /** The shipped definitions the bridge carries, as pkg/Name (resources {@code shipped/pkg/Name.msg}). */
    static final List<String> SHIPPED = List.of("builtin_interfaces/Time", "builtin_interfaces/Duration", "std_msgs/Header",
            "std_msgs/String", "std_msgs/Bool", "std_msgs/Float32", "std_msgs/Float64", "std_msgs/Int32", "std_msgs/Int64",
            "std_msgs/UInt8", "std_msgs/Empty", "geometry_msgs/Point", "geometry_msgs/Vector3", "geometry_msgs/Quaternion",
            "geometry_msgs/Pose", "geometry_msgs/PoseStamped", "geometry_msgs/Twist");
    private static final JsonNodeFactory F = JsonNodeFactory.instance;
    /** An empty registry: only the shipped copies. */
    public static final TypeRegistry NONE;

    static {
        try {
            NONE = new TypeRegistry(Map.of());
        } catch (DefinitionException e) {
            throw new IllegalStateException("the bridge's own definitions do not load: " + e.format(), e);
        }
    }

    private final Map<String, MsgType> loaded;
    private final Map<String, MsgType> all = new LinkedHashMap<>();

    /** The loaded definitions by pkg/Name; each nested type must be loaded or shipped. */
    TypeRegistry(Map<String, MsgType> loaded) throws DefinitionException {
        this.loaded = Map.copyOf(loaded);
        for (String s : SHIPPED) {
            all.put(s, shipped(s));
        }
        all.putAll(loaded);
        for (MsgType t : all.values()) {
            for (MsgField f : t.fields()) {
                if (f.type().message() != null && !all.containsKey(f.type().message())) {
                    throw new DefinitionException(t.file(), f.line(), f.column(), "unknown message type " + f.type().message()
                            + " (not in the loaded packages nor among the shipped definitions the bridge can nest: "
                            + String.join(", ", SHIPPED) + ")");
                }
            }
        }
        for (MsgType t : all.values()) {
            cycle(t, new HashSet<>());
        }
    }

    private void cycle(MsgType t, Set<String> path) throws DefinitionException {
        if (!path.add(t.fullName())) {
            return;
        }
        for (MsgField f : t.fields()) {
            if (f.type().message() != null) {
                if (path.contains(f.type().message())) {
                    throw new DefinitionException(t.file(), f.line(), f.column(), t.fullName() + " contains itself through " + f.name());
                }
                cycle(all.get(f.type().message()), path);
            }
        }
        path.remove(t.fullName());
    }

    private static MsgType shipped(String fullName) {
        String res = "shipped/" + fullName + ".msg";
        try (InputStream in = TypeRegistry.class.getResourceAsStream(res)) {
            if (in == null) {
                throw new IllegalStateException("missing resource " + res);
            }
            int slash = fullName.indexOf('/');
            return MsgParser.parse("shipped:" + fullName + ".msg", fullName.substring(0, slash), fullName.substring(slash + 1),
                    new String(in.readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException | DefinitionException e) {
            throw new IllegalStateException("the bridge's definition of " + fullName + " does not load: " + e, e);
        }
    }

    /** Whether the type comes from a loaded package (then the bridge encodes it, whatever else ships it). */
    public boolean isLoaded(String fullName) {
        return loaded.containsKey(fullName);
    }

    /** A loaded or shipped-copy definition, or null. */
    public MsgType get(String fullName) {
        return all.get(fullName);
    }

    /** The loaded packages' types, by pkg/Name. */
    public Map<String, MsgType> loaded() {
        return loaded;
    }

    /** A message of the type with every field at its default: the definition's, else ROS 2's zero value. */
    public ObjectNode template(MsgType t) {
        ObjectNode o = F.objectNode();
        for (MsgField f : t.fields()) {
            o.set(f.name(), initial(f));
        }
        return o;
    }

    private JsonNode initial(MsgField f) {
        if (f.defaultValue() != null) {
            return f.defaultValue().deepCopy();
        }
        FieldType ft = f.type();
        if (ft.array() == FieldType.Array.FIXED) {
            ArrayNode a = F.arrayNode();
            for (int i = 0; i < ft.size(); i++) {
                a.add(zero(ft.element()));
            }
            return a;
        }
        return ft.isArray() ? F.arrayNode() : zero(ft);
    }

    /** The zero value of one element. */
    JsonNode zero(FieldType element) {
        return element.primitive() != null ? Values.zero(element.primitive()) : template(all.get(element.message()));
    }
}
