package org.miron.runtime.broker;

import org.miron.runtime.Contexts;
import java.io.IOException;
import java.nio.file.Path;
import java.util.logging.Logger;
import org.miron.runtime.Endpoints;
import org.miron.runtime.bus.BusLink;
import org.zeromq.ZContext;

/**
 * The MIRoN broker: the request path to the skill interface and the publish/subscribe bus with
 * its last-value cache, each on its own thread. Binds in {@link #start()} so a busy port fails
 * the caller instead of a background thread. Components in the same process connect through
 * {@link #local()} rather than sockets.
 */
public final class Broker implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(Broker.class.getName());
    private final Endpoints endpoints;
    private final Path cacheFile; // null: the cache lives in memory only
    private final ZContext ctx = Contexts.create();
    private final LastValueCache cache = new LastValueCache(10_000);
    private RequestProxy requests;
    private BusProxy bus;
    private Thread requestThread;
    private Thread busThread;

    private Thread snapshotThread;
    private CacheFile snapshot;

    public Broker(Endpoints endpoints) {
        this(endpoints, null);
    }

    /** @param cacheFile where the last-value cache is snapshotted and reloaded from on start; null: none */
    public Broker(Endpoints endpoints, Path cacheFile) {
        this.endpoints = endpoints;
        this.cacheFile = cacheFile;
    }

    public Broker start() {
        if (cacheFile != null) {
            snapshot = new CacheFile(cacheFile, cache);
            try {
                int n = snapshot.load();
                LOG.info("broker: " + n + " cached messages restored from " + cacheFile);
            } catch (IOException | RuntimeException e) {
                ctx.close();
                throw new IllegalStateException("broker cannot load its cache file " + cacheFile + ": " + e.getMessage(), e);
            }
        }
        requests = new RequestProxy(ctx, endpoints.request(), endpoints.skill());
        bus = new BusProxy(ctx, endpoints.busIn(), endpoints.busOut(), cache);
        try {
            requests.bind();
            bus.bind();
        } catch (RuntimeException e) {
            ctx.close();
            throw new IllegalStateException("broker cannot bind its endpoints: " + e.getMessage(), e);
        }
        requestThread = new Thread(requests, "broker-requests");
        busThread = new Thread(bus, "broker-bus");
        requestThread.setDaemon(true);
        busThread.setDaemon(true);
        requestThread.start();
        busThread.start();
        if (snapshot != null) {
            snapshotThread = new Thread(this::snapshotLoop, "broker-cache-file");
            snapshotThread.setDaemon(true);
            snapshotThread.start();
        }
        LOG.info("broker: requests " + endpoints.request() + " -> " + endpoints.skill()
                + ", bus " + endpoints.busIn() + " -> " + endpoints.busOut());
        return this;
    }

    /**
     * Bus connections for components in this process: no sockets between them and the broker,
     * the same topics, bodies, order and cache replay (see {@link LocalBus}). After {@link #start}.
     */
    public BusLink local() {
        if (bus == null) {
            throw new IllegalStateException("broker not started");
        }
        return (name, subscriptions, handler) -> new LocalBus(bus, name, subscriptions, handler);
    }

    /** Number of topics held by the last-value cache (diagnostics, tests). */
    public int cachedTopics() {
        return cache.size();
    }

    private void snapshotLoop() {
        while (!Thread.currentThread().isInterrupted()) {
            try {
                Thread.sleep(CacheFile.INTERVAL_MS);
            } catch (InterruptedException e) {
                return;
            }
            snapshot.saveIfChanged();
        }
    }

    /** This run's epoch, announced on {@code miron.broker.hello}; a new epoch means a restarted broker. */
    public String epoch() {
        return bus.epoch();
    }

    /** Messages forwarded but refused by the cache as invalid (diagnostics, tests). */
    public long refusedByCache() {
        return bus == null ? 0 : bus.refused();
    }

    @Override
    public void close() {
        if (requests != null) {
            requests.stop();
            bus.stop();
            join(requestThread);
            join(busThread);
        }
        if (snapshotThread != null) {
            snapshotThread.interrupt();
            join(snapshotThread);
            snapshot.saveIfChanged(); // the last state, on a clean stop
        }
        ctx.close();
    }

    private static void join(Thread t) {
        try {
            t.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
