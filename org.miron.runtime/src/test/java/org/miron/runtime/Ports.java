package org.miron.runtime;

/** Free loopback ports, so tests never use the default MIRoN ports nor collide with other runs. */
public final class Ports {
    private Ports() {
    }

    public static Endpoints endpoints() {
        return Endpoints.freeLoopback();
    }
}
