package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;

import java.io.File;

import org.junit.Test;
import org.miron.bt.formatting2.BtFormatting;

/** The formatter indents by element depth and keeps comments, quotes and TreeNodesModel. */
public class FormatterTest {

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
}
