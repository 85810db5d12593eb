package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;

import java.io.File;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.junit.Test;
import org.miron.bt.bt.AlwaysSuccess;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.Import;
import org.miron.bt.bt.Sequence;
import org.miron.bt.bt.SubtreePlus;
import org.miron.bt.formatting2.BtFormatting;

/**
 * The formatter indents by element depth and keeps comments, quotes and TreeNodesModel; parsed files
 * keep their blank lines, models without text get one between trees.
 */
public class FormatterTest {

    /** Issue 23, item 10: the shipped trees are what the formatter makes of them. */
    @Test
    public void theExampleTreesAreFormatterClean() throws Exception {
        File[] examples = new File("..", "examples").listFiles(File::isDirectory);
        int checked = 0;
        for (File example : examples) {
            for (File tree : example.listFiles((dir, name) -> name.endsWith(".bt"))) {
                String text = java.nio.file.Files.readString(tree.toPath());
                assertEquals(tree.toString(), text, BtFormatting.format(BtFiles.parse(text, tree)));
                checked++;
            }
        }
        assertEquals(true, checked >= 2);
    }

    @Test
    public void messyFileBecomesTidy() throws Exception {
        String messy = "<?xml version=\"1.0\"?>\n"
                + "<!-- mission -->\n"
                + "<root   main_tree_to_execute = 'Main'><include path=\"inc/localization.bt\" />\n"
                + "<BehaviorTree ID=\"Main\"><Sequence name=\"top\">\n"
                + "<Condition ID=\"BatteryOK\"/>\n"
                + "        <!-- go -->\n"
                + "<Inverter><Action ID=\"b\"   x=\"1\"/></Inverter></Sequence></BehaviorTree>\n"
                + "<TreeNodesModel>\n"
                + "<Action ID=\"b\"/>\n"
                + "</TreeNodesModel></root>";
        String tidy = "<?xml version=\"1.0\"?>\n"
                + "<!-- mission -->\n"
                + "<root main_tree_to_execute='Main'>\n"
                + "  <include path=\"inc/localization.bt\"/>\n"
                + "  <BehaviorTree ID=\"Main\">\n"
                + "    <Sequence name=\"top\">\n"
                + "      <Condition ID=\"BatteryOK\"/>\n"
                + "      <!-- go -->\n"
                + "      <Inverter>\n"
                + "        <Action ID=\"b\" x=\"1\"/>\n"
                + "      </Inverter>\n"
                + "    </Sequence>\n"
                + "  </BehaviorTree>\n"
                + "  <TreeNodesModel>\n"
                + "<Action ID=\"b\"/>\n"
                + "</TreeNodesModel>\n"
                + "</root>\n";
        assertEquals(tidy, BtFormatting.format(BtFiles.parse(messy, new File(BtFiles.RESOURCES, "valid/messy.bt"))));
    }

    /** A model built in memory (the woven tree) is serialized, then formatted with blank lines between trees. */
    @Test
    public void aModelWithoutTextIsPrintedTidy() throws Exception {
        BtFactory f = BtFactory.eINSTANCE;
        BTModel model = f.createBTModel();
        model.getAttributes().add(attribute("main_tree_to_execute", "Main"));
        Import include = f.createImport();
        include.setImportURI("inc/localization.bt");
        model.getImports().add(include);
        BehaviorTree sub = f.createBehaviorTree();
        sub.setName("Sub");
        AlwaysSuccess ok = f.createAlwaysSuccess();
        ok.setTag("AlwaysSuccess");
        sub.getNodes().add(ok);
        SubtreePlus call = f.createSubtreePlus();
        call.setTag("SubTreePlus");
        call.setBehaviorTree(sub);
        call.getAttributes().add(attribute("goal", "{a & b}"));
        Sequence sequence = f.createSequence();
        sequence.setTag("Sequence");
        sequence.getAttributes().add(attribute("name", "top"));
        sequence.getNodes().add(call);
        BehaviorTree main = f.createBehaviorTree();
        main.setName("Main");
        main.getNodes().add(sequence);
        model.getTrees().add(main);
        model.getTrees().add(sub);
        XtextResourceSet set = BtFiles.INJECTOR.getInstance(XtextResourceSet.class);
        set.createResource(URI.createFileURI(new File(BtFiles.RESOURCES, "valid/printed.bt").getAbsolutePath()))
                .getContents().add(model);

        assertEquals("<root main_tree_to_execute=\"Main\">\n"
                + "  <include path=\"inc/localization.bt\"/>\n"
                + "\n"
                + "  <BehaviorTree ID=\"Main\">\n"
                + "    <Sequence name=\"top\">\n"
                + "      <SubTreePlus ID=\"Sub\" goal=\"{a &amp; b}\"/>\n"
                + "    </Sequence>\n"
                + "  </BehaviorTree>\n"
                + "\n"
                + "  <BehaviorTree ID=\"Sub\">\n"
                + "    <AlwaysSuccess/>\n"
                + "  </BehaviorTree>\n"
                + "\n"
                + "</root>\n", BtFormatting.print(model));
    }

    private static Attribute attribute(String name, String value) {
        Attribute a = BtFactory.eINSTANCE.createAttribute();
        a.setName(name);
        a.setValue(value);
        return a;
    }
}
