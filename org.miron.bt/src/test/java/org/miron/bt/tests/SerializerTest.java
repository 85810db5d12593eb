package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.serializer.ISerializer;
import org.junit.Test;
import org.miron.bt.bt.Action;
import org.miron.bt.bt.AlwaysSuccess;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.CustomControl;
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

    /** The closing name of a compact element is not in the model: it is written from the tag. */
    @Test
    public void compactElementsWithChildrenAreClosedWithTheirTag() throws Exception {
        BtFactory f = BtFactory.eINSTANCE;
        CustomControl rate = f.createCustomControl();
        rate.setTag("RateController");
        Attribute hz = f.createAttribute();
        hz.setName("hz");
        hz.setValue("1");
        rate.getAttributes().add(hz);
        AlwaysSuccess child = f.createAlwaysSuccess();
        child.setTag("AlwaysSuccess");
        rate.getNodes().add(child);
        BehaviorTree tree = f.createBehaviorTree();
        tree.setName("Main");
        tree.getNodes().add(rate);
        BTModel model = f.createBTModel();
        model.getTrees().add(tree);
        File file = new File(BtFiles.RESOURCES, "valid/compact_with_children.bt");
        XtextResource resource = BtFiles.parse("<root/>", file);
        resource.getContents().set(0, model);

        String text = serializer.serialize(model);
        // Opening and closing name (the serializer spaces tokens its own way when there is no node model).
        assertEquals(text, 2, text.split("RateController", -1).length - 1);
        BTModel again = BtFiles.model(BtFiles.parse(text, file));
        assertTrue(text, EcoreUtil.equals(model, again));
    }

    @Test
    public void aRenamedCompactElementGetsTheNewClosingName() throws Exception {
        File file = new File(BtFiles.RESOURCES, "valid/compact_with_children.bt");
        XtextResource resource = BtFiles.load(file);
        CustomControl scheduler = (CustomControl) BtFiles.model(resource).getTrees().get(0).getNodes().get(0);
        scheduler.setTag("RoundRobin");
        String text = serializer.serialize(BtFiles.model(resource));
        assertTrue(text, text.contains("<RoundRobin policy=\"round_robin\">"));
        assertTrue(text, text.contains("</RoundRobin>"));
        assertTrue(text, BtFiles.parse(text, file).getErrors().isEmpty());
    }
}
