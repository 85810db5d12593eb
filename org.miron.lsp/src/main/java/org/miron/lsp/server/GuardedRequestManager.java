package org.miron.lsp.server;

import java.lang.System.Logger.Level;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;

import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.xtext.ide.server.concurrent.RequestManager;
import org.eclipse.xtext.service.OperationCanceledManager;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.xbase.lib.Exceptions;
import org.eclipse.xtext.xbase.lib.Functions.Function0;
import org.eclipse.xtext.xbase.lib.Functions.Function1;
import org.eclipse.xtext.xbase.lib.Functions.Function2;

import com.google.inject.Inject;
import com.google.inject.Singleton;

/**
 * Xtext's request manager with two changes.
 * <p>
 * A read asked for from inside a running read (Xtext's rename does: {@code RenameService2} waits on
 * {@code ILanguageServerAccess.doRead} inside the rename request) runs at once on the caller's
 * thread, under the outer read's cancel indicator. Xtext queues it instead, behind any write that
 * arrived meanwhile; that write waits for the outer read, which waits for the queued one: the
 * server stalled (no diagnostics, no answers) until the next write cancelled the queued read. A
 * rename and an edit or a change on disk at the same moment did that, and the background rename
 * warm-up ({@link RenameWarmUp}) met it regularly. The outer read holds off every write until it
 * ends, so the inner one sees the same state it would have seen.
 * <p>
 * The last resort behind the services' own handling of broken text: a request that still throws
 * is logged with its stack trace on standard error and answered with a short LSP error
 * (RequestFailed, {@link #MESSAGE}), not an internal error whose data is the stack trace, which
 * editors show as a popup. Cancellation, also wrapped, passes through unchanged.
 */
@Singleton
public class GuardedRequestManager extends RequestManager {
    /** How every guarded failure's message starts (the fuzz test counts these as bugs). */
    public static final String MESSAGE = "The MIRoN language server could not answer this request on the current text";
    private static final System.Logger LOG = System.getLogger(GuardedRequestManager.class.getName());

    private final OperationCanceledManager cancellation;

    @Inject
    public GuardedRequestManager(ExecutorService parallel, OperationCanceledManager cancellation) {
        super(parallel, cancellation);
        this.cancellation = cancellation;
    }

    /** The cancel indicator of the read running on this thread, if one is. */
    private final ThreadLocal<CancelIndicator> reading = new ThreadLocal<>();

    // Not synchronized: a nested read runs outside the manager's lock, which new requests need.
    @Override
    public <V> CompletableFuture<V> runRead(Function1<? super CancelIndicator, ? extends V> request) {
        CancelIndicator outer = reading.get();
        if (outer != null) {
            return nested(outer, request);
        }
        return queued(request);
    }

    private synchronized <V> CompletableFuture<V> queued(Function1<? super CancelIndicator, ? extends V> request) {
        return super.runRead(cancelIndicator -> {
            reading.set(cancelIndicator);
            try {
                return guarded(() -> request.apply(cancelIndicator));
            } finally {
                reading.remove();
            }
        });
    }

    /** The nested read's failure goes to its caller as it is; the outer read is the guarded one. */
    private <V> CompletableFuture<V> nested(CancelIndicator outer, Function1<? super CancelIndicator, ? extends V> request) {
        CompletableFuture<V> result = new CompletableFuture<>();
        try {
            cancellation.checkCanceled(outer);
            result.complete(request.apply(outer));
        } catch (Throwable e) {
            if (cancellation(e) != null) {
                result.cancel(true);
            } else {
                result.completeExceptionally(e);
            }
        }
        return result;
    }

    @Override
    public synchronized <U, V> CompletableFuture<V> runWrite(Function0<? extends U> nonCancellable,
            Function2<? super CancelIndicator, ? super U, ? extends V> request) {
        return super.runWrite(nonCancellable,
                (cancelIndicator, written) -> guarded(() -> request.apply(cancelIndicator, written)));
    }

    private <V> V guarded(Function0<V> request) {
        try {
            return request.apply();
        } catch (ResponseErrorException meaningful) {
            throw meaningful;
        } catch (Exception | StackOverflowError e) { // Xtext also throws checked exceptions sneakily
            Throwable cancelled = cancellation(e);
            if (cancelled != null) {
                // Unwrapped: Xtext's request manager recognizes only the cancellation itself.
                throw Exceptions.sneakyThrow(cancelled);
            }
            Throwable cause = e;
            while ((cause instanceof ExecutionException || cause instanceof CompletionException) && cause.getCause() != null) {
                cause = cause.getCause();
            }
            if (cause instanceof ResponseErrorException) {
                throw (ResponseErrorException) cause;
            }
            LOG.log(Level.WARNING, MESSAGE, e);
            throw new ResponseErrorException(new ResponseError(ResponseErrorCode.RequestFailed,
                    MESSAGE + " (" + e.getClass().getSimpleName() + "); the server log has the details.", null));
        }
    }

    /** The cancellation that ended a request, also when wrapped (in a future's ExecutionException); else null. */
    private Throwable cancellation(Throwable e) {
        for (Throwable cause = e; cause != null; cause = cause.getCause() == cause ? null : cause.getCause()) {
            if (cancellation.isOperationCanceledException(cause)) {
                return cause;
            }
        }
        return null;
    }
}
