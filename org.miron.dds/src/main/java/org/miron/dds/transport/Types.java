package org.miron.dds.transport;

import java.lang.reflect.InvocationTargetException;
import org.miron.dds.types.TypeRegistry;
import us.ihmc.pubsub.TopicDataType;

/**
 * Message types by name: a ROS 2 type {@code pkg/Name} as the IHMC library ships it (class
 * {@code pkg.msg.dds.NamePubSubType}: std_msgs, sensor_msgs, geometry_msgs, nav_msgs ...), or one of
 * RoQME's own types by its IDL struct name ({@code RoqmeEstimate}, {@code RoqmeDoubleContext} ...).
 */
final class Types {
    private Types() {
    }

    /**
     * A fresh type instance (each holds its own CDR buffers), or null for an unknown name or a key
     * asked of a type that has none (only RoQME's types are keyed; ROS 2's never are).
     */
    static TopicDataType<?> lookup(String name, boolean keyed) {
        return lookup(name, keyed, TypeRegistry.NONE);
    }

    /**
     * As {@link #lookup(String, boolean)}, a loaded package's definition first (it wins over the
     * library's class of the same name), then the library's, then the bridge's own copies.
     */
    static TopicDataType<?> lookup(String name, boolean keyed, TypeRegistry registry) {
        if (registry.isLoaded(name)) {
            return keyed ? null : new DefinedType(registry, registry.get(name));
        }
        TopicDataType<?> shipped = library(name, keyed);
        if (shipped != null || keyed || registry.get(name) == null) {
            return shipped;
        }
        return new DefinedType(registry, registry.get(name));
    }

    /** Whether the library ships a class for the ROS 2 type. */
    static boolean shipped(String name) {
        return library(name, false) != null;
    }

    private static TopicDataType<?> library(String name, boolean keyed) {
        RoqmeType.Kind k = RoqmeType.Kind.of(name);
        if (k != null) {
            return new RoqmeType(k, keyed);
        }
        if (keyed) {
            return null;
        }
        int slash = name.indexOf('/');
        if (slash <= 0 || slash != name.lastIndexOf('/') || !name.matches("[a-z][a-z0-9_]*/[A-Z][A-Za-z0-9]*")) {
            return null;
        }
        String cls = name.substring(0, slash) + ".msg.dds." + name.substring(slash + 1) + "PubSubType";
        try {
            Class<?> c = Class.forName(cls, true, Types.class.getClassLoader());
            if (!TopicDataType.class.isAssignableFrom(c)) {
                return null;
            }
            return (TopicDataType<?>) c.getDeclaredConstructor().newInstance();
        } catch (ClassNotFoundException | NoSuchMethodException | InstantiationException | IllegalAccessException
                | InvocationTargetException | LinkageError e) {
            return null;
        }
    }
}
