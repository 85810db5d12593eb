package org.miron.runtime.recording;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** A bus log as a killed process leaves it reads up to its last complete line; anything else malformed is refused with its line. */
public class BusLogReaderTest {
    private static final String HEADER = "{\"format\":\"miron-bus-log\",\"version\":1}\n";
    private static final String EVENT = "{\"timeUs\":1764640000000000,\"topic\":\"miron.decision\",\"message\":{\"seq\":1}}\n";

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private Path write(String text) throws Exception {
        Path file = tmp.newFile().toPath();
        Files.writeString(file, text);
        return file;
    }

    @Test
    public void aLastLineCutShortIsLeftOut() throws Exception {
        List<BusLogReader.BusEvent> events = BusLogReader.read(write(HEADER + EVENT + EVENT.substring(0, 30)));
        assertEquals(1, events.size());
        assertEquals("miron.decision", events.get(0).topic());
        assertEquals(1764640000000000L, events.get(0).timeUs());
        assertEquals(1, events.get(0).message().path("seq").asInt());
    }

    @Test
    public void aMalformedLineInTheMiddleIsRefusedWithItsNumber() throws Exception {
        Path file = write(HEADER + EVENT + "{\"topic\":\"x\"}\n" + EVENT);
        BtlogFormatException e = assertThrows(BtlogFormatException.class, () -> BusLogReader.read(file));
        assertTrue(e.getMessage(), e.getMessage().endsWith(":3: not a bus event {\"timeUs\",\"topic\",\"message\"}"));
    }

    @Test
    public void aFileWithoutTheHeaderIsNotABusLog() throws Exception {
        Path file = write(EVENT);
        BtlogFormatException e = assertThrows(BtlogFormatException.class, () -> BusLogReader.read(file));
        assertTrue(e.getMessage(), e.getMessage().contains("not a bus log"));
    }

    @Test
    public void aTransitionWithAnUnknownStatusIsRefused() throws Exception {
        byte[] header = "BTCPP4-FileLogger2\u0001\u0007\u0000\u0000\u0000<root/>".getBytes("ISO-8859-1");
        byte[] bytes = new byte[header.length + 8 + 9];
        System.arraycopy(header, 0, bytes, 0, header.length);
        bytes[bytes.length - 1] = 9; // status 9
        BtlogFormatException e = assertThrows(BtlogFormatException.class, () -> BtlogReader.parse(bytes, "x.btlog"));
        assertTrue(e.getMessage(), e.getMessage().contains("transition 1 has status 9"));
    }
}
