package org.miron.runtime.recording;

import java.io.IOException;

/** A file that is not a FileLogger2 recording, or one whose header is cut short: the reason, for people. */
public final class BtlogFormatException extends IOException {
    public BtlogFormatException(String message) {
        super(message);
    }
}
