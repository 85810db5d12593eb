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
 * The last resort behind the services' own handling of broken text: a request that still throws
 * is logged with its stack trace on standard error and answered with a short LSP error
 * (RequestFailed, {@link #MESSAGE}), not an internal error whose data is the stack trace, which
 * editors show as a popup. Cancellation passes through unchanged.
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

    @Override
    public synchronized <V> CompletableFuture<V> runRead(Function1<? super CancelIndicator, ? extends V> request) {
        return super.runRead(cancelIndicator -> guarded(() -> request.apply(cancelIndicator)));
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
            if (cancellation.isOperationCanceledException(e)) {
                throw Exceptions.sneakyThrow(e);
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
}
