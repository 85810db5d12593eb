package org.miron.runtime.roqme;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.atomic.AtomicLong;
import org.miron.runtime.Json;

/** Counters of the live provider and the body of its {@code roqme.status} message. */
final class ProviderStatus {
    final AtomicLong contexts = new AtomicLong();
    final AtomicLong malformed = new AtomicLong();
    final AtomicLong unknown = new AtomicLong();
    final AtomicLong badType = new AtomicLong();
    final AtomicLong overflow = new AtomicLong();
    private volatile String lastErrorKind;
    private volatile String lastErrorMessage;
    private volatile long lastErrorTime;

    void bad(ContextDecoder.Problem p, String message, long time) {
        (p == ContextDecoder.Problem.MALFORMED ? malformed : p == ContextDecoder.Problem.UNKNOWN ? unknown : badType)
                .incrementAndGet();
        lastErrorKind = p.name().toLowerCase(java.util.Locale.ROOT);
        lastErrorMessage = message;
        lastErrorTime = time;
    }

    long badTotal() {
        return malformed.get() + unknown.get() + badType.get();
    }

    String body(String model, long time, long ticks, long fired, String state) {
        ObjectNode o = Json.object();
        o.put("time", time);
        o.put("model", model);
        o.put("state", state);
        ObjectNode c = o.putObject("counters");
        c.put("contexts", contexts.get());
        c.put("malformedInput", malformed.get());
        c.put("unknownInput", unknown.get());
        c.put("badTypeInput", badType.get());
        c.put("droppedInput", overflow.get());
        c.put("ticks", ticks);
        c.put("fired", fired);
        if (lastErrorKind != null) {
            ObjectNode e = o.putObject("lastError");
            e.put("kind", lastErrorKind);
            e.put("message", lastErrorMessage);
            e.put("time", lastErrorTime);
        }
        return Json.write(o);
    }
}
