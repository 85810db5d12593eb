package org.miron.executor;

/** A clock the test moves by hand. */
final class FakeClock implements MillisClock {
    long now = 1_000_000;

    @Override
    public long nowMillis() {
        return now;
    }

    void advance(long millis) {
        now += millis;
    }
}
