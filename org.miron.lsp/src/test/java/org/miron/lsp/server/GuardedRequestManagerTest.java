package org.miron.lsp.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.xtext.service.OperationCanceledManager;
import org.junit.After;
import org.junit.Test;

/**
 * The request manager with real threads: a read asked for inside a running read (Xtext's rename
 * does that) must not wait behind a write that came in between, which itself waits for the outer
 * read. With Xtext's own manager this stalled the server until the next write (the Neovim test's
 * "change on disk" saw no diagnostics while the rename warm-up ran).
 */
public class GuardedRequestManagerTest {
    private final ExecutorService pool = Executors.newCachedThreadPool();
    private final GuardedRequestManager manager = new GuardedRequestManager(pool, new OperationCanceledManager());

    @After
    public void tearDown() {
        manager.shutdown();
        pool.shutdownNow();
    }

    @Test
    public void aNestedReadRunsInTheOuterOne() throws Exception {
        AtomicReference<Thread> outerThread = new AtomicReference<>();
        AtomicReference<Thread> innerThread = new AtomicReference<>();
        CompletableFuture<String> outer = manager.runRead(cancel -> {
            outerThread.set(Thread.currentThread());
            CompletableFuture<String> inner = manager.runRead(c -> {
                innerThread.set(Thread.currentThread());
                return "inner";
            });
            return "outer+" + get(inner, 60);
        });
        assertEquals("outer+inner", outer.get(60, TimeUnit.SECONDS));
        assertEquals(outerThread.get(), innerThread.get());
    }

    /** The write that came in between cancels the outer read, and both end. */
    @Test
    public void aWriteDuringANestedReadDoesNotStallTheServer() throws Exception {
        CountDownLatch outerRunning = new CountDownLatch(1);
        CountDownLatch writeSubmitted = new CountDownLatch(1);
        CompletableFuture<String> outer = manager.runRead(cancel -> {
            outerRunning.countDown();
            await(writeSubmitted);
            // As RenameService2 does: doRead(...).get() inside the rename request.
            // Longer than the test waits for the write: a stall is not ended by this timeout.
            return get(manager.runRead(c -> "inner"), 180);
        });
        assertTrue(outerRunning.await(60, TimeUnit.SECONDS));
        CompletableFuture<String> write = manager.runWrite(() -> "built", (cancel, built) -> built);
        writeSubmitted.countDown();
        try {
            assertEquals("built", write.get(60, TimeUnit.SECONDS));
        } catch (TimeoutException stalled) {
            fail("the write waits for the outer read, which waits for its nested read behind the write");
        }
        try {
            outer.get(60, TimeUnit.SECONDS);
            fail("the outer read was not cancelled by the write");
        } catch (CancellationException cancelled) {
            // cancelled by the write, as any read running when a write comes: not a failure
        } catch (ExecutionException failed) {
            throw new AssertionError("the outer read failed instead of being cancelled", failed);
        }
        // And the manager serves on.
        assertEquals("after", manager.runRead(c -> "after").get(60, TimeUnit.SECONDS));
    }

    private static <V> V get(CompletableFuture<V> future, int seconds) {
        try {
            return future.get(seconds, TimeUnit.SECONDS);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private static void await(CountDownLatch latch) {
        try {
            latch.await(60, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
