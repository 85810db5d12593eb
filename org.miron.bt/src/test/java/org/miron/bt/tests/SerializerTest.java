package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;

import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.serializer.ISerializer;
import org.junit.Test;
import org.miron.bt.bt.Action;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.Sequence;

/** Changed models serialize back to well-formed XML with the values escaped. */
public class SerializerTest {
    private final ISerializer serializer = BtFiles.INJECTOR.getInstance(ISerializer.class);

    @Test
    public void changedValuesAreEscapedAndReadBack() throws Exception {
        File file = new File(BtFiles.RESOURCES, "valid/blackboard_ports.bt");
        XtextResource resource = BtFiles.load(file);
        Sequence sequence = (Sequence) BtFiles.model(resource).getTrees().get(0).getNodes().get(0);
        Action move = (Action) sequence.getNodes().get(1);
        Attribute note = BtFactory.eINSTANCE.createAttribute();
        note.setName("note");
        note.setValue("fast & \"safe\" <always>");
        move.getAttributes().add(note);

        String text = serializer.serialize(BtFiles.model(resource));
        assertTrue(text, text.contains("note=\"fast &amp; &quot;safe&quot; &lt;always&gt;\""));
        // The untouched parts keep their original text.
        assertTrue(text, text.contains("speed=\"${max_speed}\" mode=\"=\""));

        BTModel again = BtFiles.model(BtFiles.parse(text, file));
        Action reread = (Action) ((Sequence) again.getTrees().get(0).getNodes().get(0)).getNodes().get(1);
        assertEquals("fast & \"safe\" <always>", reread.attribute("note"));
    }
}
