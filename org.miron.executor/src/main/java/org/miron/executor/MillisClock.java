package org.miron.executor;

/** Source of time in milliseconds; injectable so that Timeout can be tested without waiting. */
@FunctionalInterface
public interface MillisClock {
    MillisClock SYSTEM = System::currentTimeMillis;

    long nowMillis();
}
