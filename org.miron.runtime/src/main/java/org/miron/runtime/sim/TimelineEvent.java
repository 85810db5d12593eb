package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Something a simulated run recorded for its report, as the bus would have carried it: {@code at}
 * ms after the start, the topic ({@code roqme.estimate}, {@code roqme.context},
 * {@code roqme.observation}, {@code miron.decision}) and the message body.
 */
public record TimelineEvent(long at, String topic, ObjectNode body) {
}
