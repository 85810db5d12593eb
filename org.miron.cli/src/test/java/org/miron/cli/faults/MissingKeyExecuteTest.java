package org.miron.cli.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Ports;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;

/**
 * Issue 30, item 2, as a user meets it: {@code miron execute} on a tree whose SubTree remaps goal
 * to a key nothing writes. The skill interface never receives the skill with the placeholder; the
 * tree fails and the console says which node, port and key, and through which remapping.
 */
public class MissingKeyExecuteTest {
    private static final long TIMEOUT = 30_000;
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private final Endpoints ep = Ports.endpoints();

    @Test
    public void version3SubTreePlus() throws Exception {
        run("<root>", "SubTreePlus");
    }

    @Test
    public void version4SubTree() throws Exception {
        run("<root BTCPP_format=\"4\">", "SubTree");
    }

    private void run(String root, String subtree) throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("mission.bt");
        Files.writeString(tree, "<?xml version=\"1.0\"?>\n" + root.replace(">", " main_tree_to_execute=\"Main\">") + "\n"
                + "  <BehaviorTree ID=\"Main\">\n    <Sequence name=\"mission\">\n"
                + "      <Action ID=\"OpenDrawer\"/>\n"
                + "      <" + subtree + " ID=\"Navigate\" name=\"travel\" goal=\"{ward}\"/>\n"
                + "      <Action ID=\"Handover\"/>\n    </Sequence>\n  </BehaviorTree>\n"
                + "  <BehaviorTree ID=\"Navigate\">\n    <Action ID=\"MoveBase\" name=\"drive\" goal=\"{goal}\"/>\n"
                + "  </BehaviorTree>\n</root>\n");
        try (Broker broker = new Broker(ep).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), SkillTable.defaults())
                        .start();
                RuntimeProcess execute = RuntimeProcess.start(tmp.getRoot().toPath(), "execute", "execute",
                        tree.toString(), "--period", "20", "--request", ep.request(), "--skill-events",
                        ep.skillEvents(), "--bus-in", ep.busIn(), "--bus-out", ep.busOut())) {
            assertEquals("exit status (1: the tree failed)\n" + execute.output(), 1, execute.awaitExit(TIMEOUT));
            String output = execute.output();
            assertTrue(output, output.contains("Main/mission/travel/drive: skill MoveBase not pushed: port goal=\"{goal}\" "
                    + "reads blackboard key 'goal', which has no value (remapped by Main/mission/travel (goal=\"{ward}\") "
                    + "to the parent's 'ward', nothing has written 'ward')\n"));
            assertTrue(output, output.contains("tree Main finished: FAILURE"));
            List<String> pushed = skills.pushed().stream().map(s -> s.path("name").asText()).collect(Collectors.toList());
            assertEquals("what reached the skill interface", List.of("OpenDrawer"), pushed);
        }
    }
}
