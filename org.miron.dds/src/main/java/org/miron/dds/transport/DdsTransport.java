package org.miron.dds.transport;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.function.Consumer;

/**
 * What the bridge needs from a DDS implementation: typed readers and writers on one domain
 * participant, with messages as JSON trees (field names as in the IDL). The one implementation,
 * {@link IhmcTransport}, sits on IHMC's ROS 2 library; nothing else in the bridge names it.
 */
public interface DdsTransport extends AutoCloseable {

    /** Receives one sample as a JSON tree, or why it could not be decoded. */
    interface Listener {
        void sample(ObjectNode message);

        void undecodable(String why);
    }

    /** A reader; {@link #matched()} counts the remote writers matched now. */
    interface Reader extends AutoCloseable {
        int matched();

        @Override
        void close();
    }

    /** A writer; {@link #matched()} counts the remote readers matched now. */
    interface Writer extends AutoCloseable {
        /** Writes the message; fields missing from {@code message} keep their IDL default. */
        void write(JsonNode message);

        int matched();

        @Override
        void close();
    }

    Reader reader(TopicSpec topic, Listener listener) throws DdsException;

    Writer writer(TopicSpec topic) throws DdsException;

    /** Matching changed on some reader or writer: a listener for logs and waits. */
    default void onMatching(Consumer<String> listener) {
    }

    @Override
    void close();
}
