package org.miron.dds.transport;

import com.eprosima.xmlschemas.fastrtps_profiles.DurabilityQosKindPolicyType;
import com.eprosima.xmlschemas.fastrtps_profiles.HistoryQosKindPolicyType;
import com.eprosima.xmlschemas.fastrtps_profiles.ReliabilityQosKindPolicyType;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.InetAddress;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.miron.dds.types.TypeRegistry;
import us.ihmc.pubsub.Domain;
import us.ihmc.pubsub.DomainFactory;
import us.ihmc.pubsub.TopicDataType;
import us.ihmc.pubsub.attributes.CommonAttributes;
import us.ihmc.pubsub.attributes.ParticipantProfile;
import us.ihmc.pubsub.attributes.PublisherAttributes;
import us.ihmc.pubsub.attributes.SubscriberAttributes;
import us.ihmc.pubsub.common.ChangeKind;
import us.ihmc.pubsub.common.MatchingInfo;
import us.ihmc.pubsub.common.SampleInfo;
import us.ihmc.pubsub.participant.Participant;
import us.ihmc.pubsub.publisher.Publisher;
import us.ihmc.pubsub.subscriber.Subscriber;
import us.ihmc.pubsub.subscriber.SubscriberListener;
import us.ihmc.ros2.ROS2NodeInterface;

/**
 * {@link DdsTransport} on IHMC's ROS 2 library (eProsima Fast-DDS through JNI). One participant
 * bound to the given addresses (the UDPv4 transport's whitelist, no shared memory, as the library's
 * ROS 2 nodes do). Used at the level of its pub-sub API rather than its ROS 2 node: a node puts its
 * namespace into the DDS partition (docs/dds.md), while ROS 2 topics need none and RoQME's need
 * theirs; topic names and partitions are set here exactly as {@link TopicSpec} says.
 */
public final class IhmcTransport implements DdsTransport {
    private final Domain domain;
    private final Participant participant;
    private final List<Consumer<String>> matchingListeners = new CopyOnWriteArrayList<>();
    private final Map<String, Boolean> keyedTypes = new HashMap<>(); // registered types: keyed or not
    private final TypeRegistry registry;

    /**
     * @param domainId   the DDS domain (ROS_DOMAIN_ID)
     * @param name       the participant's name, as other DDS tools show it
     * @param interfaces the addresses to bind (127.0.0.1: this machine only)
     */
    public IhmcTransport(int domainId, String name, List<InetAddress> interfaces) throws DdsException {
        this(domainId, name, interfaces, TypeRegistry.NONE);
    }

    /** As above, with the types of the loaded message packages too. */
    public IhmcTransport(int domainId, String name, List<InetAddress> interfaces, TypeRegistry registry) throws DdsException {
        this.registry = registry;
        try {
            domain = DomainFactory.getDomain(DomainFactory.PubSubImplementation.FAST_RTPS);
            ParticipantProfile profile = ROS2NodeInterface.createParticipantAttributes(domainId, false,
                    interfaces.toArray(new InetAddress[0]));
            profile.name(name);
            participant = domain.createParticipant(profile);
        } catch (IOException | RuntimeException | LinkageError e) {
            throw new DdsException("cannot create the DDS participant on domain " + domainId + ": " + e, e);
        }
    }

    /** The types this transport can carry, without a participant (for checking a configuration). */
    public static final TypeCatalog CATALOG = catalog(TypeRegistry.NONE);

    /** The types this transport can carry with the loaded packages' types. */
    public static TypeCatalog catalog(TypeRegistry registry) {
        return new TypeCatalog() {
            @Override
            public ObjectNode template(String type) {
                TopicDataType<?> t = Types.lookup(type, false, registry);
                return t == null ? null : empty(t);
            }

            @Override
            public TypeCatalog withPackages(TypeRegistry packages) {
                return catalog(packages);
            }

            @Override
            public boolean ships(String type) {
                return Types.shipped(type);
            }
        };
    }

    /** Whether the DDS library ships the ROS 2 type {@code pkg/Name} (a loaded package that redefines it wins). */
    public static boolean ships(String type) {
        return Types.shipped(type);
    }

    private static <T> ObjectNode empty(TopicDataType<T> t) {
        return t instanceof DefinedType d ? d.template() : JsonOut.of(t, t.createData());
    }

    /** The message as a JSON tree, or null with the reason given to the listener. */
    private static <T> ObjectNode json(TopicDataType<T> type, T data) {
        if (data instanceof DefinedType.Sample s) {
            if (s.error != null) {
                throw new IllegalArgumentException(s.error);
            }
            return s.json;
        }
        return JsonOut.of(type, data);
    }

    @SuppressWarnings("unchecked")
    private static <T> T fill(TopicDataType<T> type, JsonNode message) {
        if (type instanceof DefinedType d) {
            return (T) d.fill(message);
        }
        return JsonIn.fill(type, message);
    }

    /**
     * The type, registered with the participant on first use. Keyed or not is the registered type's
     * property in Fast-DDS, so one participant carries a type either keyed or unkeyed, never both.
     */
    private TopicDataType<?> type(String name, boolean keyed) throws DdsException {
        TopicDataType<?> t = Types.lookup(name, keyed, registry);
        if (t == null) {
            throw new DdsException(keyed && Types.lookup(name, false, registry) != null ? name + " has no key: only RoQME's types are keyed"
                    : "unknown message type " + name);
        }
        synchronized (this) {
            Boolean was = keyedTypes.get(t.getName());
            if (was == null) {
                domain.registerType(participant, t);
                if (keyed) {
                    NativeKeySwitch.enable(participant, t.getName(), t.getTypeSize());
                }
                keyedTypes.put(t.getName(), keyed);
            } else if (was != keyed) {
                throw new DdsException(name + " is already used " + (was ? "keyed" : "unkeyed") + " by this bridge; it cannot be both");
            }
        }
        return t;
    }

    /**
     * Fast-DDS's XML profile for the attributes, with the topic kind WITH_KEY for a keyed topic: the
     * JAXB classes the library marshals with predate the {@code <kind>} element, which Fast-DDS's
     * parser still reads.
     */
    static String withKey(String profile) throws IOException {
        int at = profile.indexOf("<topic>");
        if (at < 0 || profile.indexOf("<topic>", at + 1) >= 0) {
            throw new IOException("unexpected DDS profile: no single <topic> element");
        }
        at += "<topic>".length();
        return profile.substring(0, at) + "<kind>WITH_KEY</kind>" + profile.substring(at);
    }

    private static PublisherAttributes publisherAttributes(boolean keyed) {
        return !keyed ? PublisherAttributes.create() : new PublisherAttributes() {
            @Override
            public String marshall(String profileName) throws IOException {
                return withKey(super.marshall(profileName));
            }
        };
    }

    private static SubscriberAttributes subscriberAttributes(boolean keyed) {
        return !keyed ? SubscriberAttributes.create() : new SubscriberAttributes() {
            @Override
            public String marshall(String profileName) throws IOException {
                return withKey(super.marshall(profileName));
            }
        };
    }

    private static <A extends CommonAttributes<A>> A apply(A a, TopicDataType<?> type, TopicSpec spec) {
        a.topicDataType(type);
        a.topicName(spec.name());
        a.reliabilityKind(spec.qos().reliable() ? ReliabilityQosKindPolicyType.RELIABLE : ReliabilityQosKindPolicyType.BEST_EFFORT);
        a.durabilityKind(spec.qos().transientLocal() ? DurabilityQosKindPolicyType.TRANSIENT_LOCAL : DurabilityQosKindPolicyType.VOLATILE);
        a.historyQosPolicyKind(HistoryQosKindPolicyType.KEEP_LAST);
        a.historyDepth(spec.qos().depth());
        if (!spec.partitions().isEmpty()) {
            a.partitions(spec.partitions());
        }
        return a;
    }

    @Override
    public Reader reader(TopicSpec spec, Listener listener) throws DdsException {
        return reader(type(spec.type(), spec.keyed()), spec, listener);
    }

    private <T> Reader reader(TopicDataType<T> type, TopicSpec spec, Listener listener) throws DdsException {
        AtomicInteger matched = new AtomicInteger();
        java.util.concurrent.atomic.AtomicBoolean closed = new java.util.concurrent.atomic.AtomicBoolean();
        SubscriberListener<T> l = new SubscriberListener<>() {
            private final SampleInfo info = new SampleInfo();

            @Override
            public void onNewDataMessage(Subscriber<T> s) {
                // One sample per call: Fast-DDS calls once per arriving sample, and a take on an
                // empty reader prints a native error line each time.
                T data = type.createData();
                boolean got;
                try {
                    got = s.takeNextData(data, info);
                } catch (RuntimeException e) {
                    listener.undecodable("cannot decode a " + spec.type() + " on " + spec.name() + ": " + e.getMessage());
                    return;
                }
                if (!got || closed.get() || info.getSampleKind() != ChangeKind.ALIVE) {
                    return; // a keyed instance disposed or unregistered (its writer went): no data
                }
                ObjectNode json;
                try {
                    json = json(type, data);
                } catch (RuntimeException e) {
                    listener.undecodable("cannot read a " + spec.type() + " on " + spec.name() + ": " + e);
                    return;
                }
                listener.sample(json);
            }

            @Override
            public void onSubscriptionMatched(Subscriber<T> s, MatchingInfo info) {
                count(matched, info, "reader " + spec.name());
            }
        };
        try {
            Subscriber<T> sub = domain.createSubscriber(participant, apply(subscriberAttributes(spec.keyed()), type, spec), l);
            return new Reader() {
                @Override
                public int matched() {
                    return matched.get();
                }

                @Override
                public void close() {
                    closed.set(true); // the native delete can hang: the participant's removal takes it along
                }
            };
        } catch (IOException | RuntimeException e) {
            throw new DdsException("cannot subscribe to " + spec.name() + " (" + spec.type() + "): " + e.getMessage(), e);
        }
    }

    @Override
    public Writer writer(TopicSpec spec) throws DdsException {
        return writer(type(spec.type(), spec.keyed()), spec);
    }

    private <T> Writer writer(TopicDataType<T> type, TopicSpec spec) throws DdsException {
        AtomicInteger matched = new AtomicInteger();
        java.util.concurrent.atomic.AtomicBoolean closed = new java.util.concurrent.atomic.AtomicBoolean();
        try {
            Publisher pub = domain.createPublisher(participant, apply(publisherAttributes(spec.keyed()), type, spec),
                    (p, info) -> count(matched, info, "writer " + spec.name()));
            return new Writer() {
                @Override
                public synchronized void write(JsonNode message) {
                    if (closed.get()) {
                        throw new IllegalStateException("writer on " + spec.name() + " is closed");
                    }
                    try {
                        pub.write(fill(type, message));
                    } catch (IOException e) {
                        throw new IllegalStateException("cannot write to " + spec.name() + ": " + e.getMessage(), e);
                    }
                }

                @Override
                public int matched() {
                    return matched.get();
                }

                @Override
                public void close() {
                    closed.set(true);
                }
            };
        } catch (IOException | RuntimeException e) {
            throw new DdsException("cannot publish on " + spec.name() + " (" + spec.type() + "): " + e.getMessage(), e);
        }
    }

    private void count(AtomicInteger matched, MatchingInfo info, String what) {
        int n = info.getStatus() == MatchingInfo.MatchingStatus.MATCHED_MATCHING ? matched.incrementAndGet()
                : Math.max(0, matched.decrementAndGet());
        for (Consumer<String> l : matchingListeners) {
            l.accept(what + (info.getStatus() == MatchingInfo.MatchingStatus.MATCHED_MATCHING ? " matched" : " unmatched")
                    + ", " + n + " now");
        }
    }

    @Override
    public void onMatching(Consumer<String> listener) {
        matchingListeners.add(listener);
    }

    /**
     * Removes the participant (and with it every reader and writer). Fast-DDS's native delete can
     * block for good while a listener callback is under way (seen in the tests), so it runs on a
     * daemon thread that is given 5 s: a process that exits does not wait for it.
     */
    @Override
    public void close() {
        Thread t = new Thread(() -> domain.removeParticipant(participant), "dds-close");
        t.setDaemon(true);
        t.start();
        try {
            t.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
