package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import org.miron.executor.skills.SkillActionStrategy;
import org.miron.executor.skills.SkillRequest;
import org.miron.executor.skills.SkillResult;

/**
 * A port pointing at a blackboard key without a value (issue 30: the hospital tree's
 * {@code goal="{ward}"}, which nothing sets): no skill is pushed with it, the node fails and one
 * line names the node, the port, the key and the remapping it came through. The same trees in
 * BehaviorTree.CPP 3 (SubTreePlus) and 4 (SubTree) form.
 */
@RunWith(Parameterized.class)
public class MissingKeyTest {
    private static final String REMAPPED = "remapped by Unset/mission/travel (goal=\"{ward}\") to the parent's 'ward', "
            + "nothing has written 'ward'";

    @Parameters(name = "{0}")
    public static Collection<Object[]> files() {
        return Arrays.asList(new Object[][] { { "missing-keys.bt", 3 }, { "missing-keys-v4.xml", 4 } });
    }

    private final String file;
    private final int version;
    private final FakeSkillClient skills = new FakeSkillClient();
    private final List<String> problems = new ArrayList<>();

    public MissingKeyTest(String file, int version) {
        this.file = file;
        this.version = version;
    }

    private Tree build(String treeId) {
        ActionRegistry registry = new ActionRegistry();
        registry.setFallback(new SkillActionStrategy(skills));
        TreeContext context = new TreeContext();
        context.onProblem(problems::add);
        Tree tree = Fixtures.build(file, treeId, registry, context);
        assertEquals(version, tree.formatVersion());
        return tree;
    }

    @Test
    public void aSkillWhoseInputKeyHasNoValueIsNotPushedAndItsNodeFails() {
        Tree tree = build("Unset");
        assertEquals(NodeStatus.RUNNING, tree.tickRoot());
        // drive failed at once, the Fallback went on to its recovery
        assertEquals(List.of("RecoveryRotate"), skills.requests.stream().map(SkillRequest::name).toList());
        assertEquals(NodeStatus.FAILURE, tree.find("drive").orElseThrow().status());
        assertEquals(List.of("Unset/mission/travel/navigation/drive: skill MoveBase not pushed: port goal=\"{goal}\" "
                + "reads blackboard key 'goal', which has no value (" + REMAPPED + ")"), problems);
        skills.completeLast(SkillResult.Outcome.SUCCESS);
        assertEquals(NodeStatus.RUNNING, tree.tickRoot());
        assertEquals("Handover", skills.last().name());
        assertNoPlaceholderSent();
    }

    @Test
    public void onceTheKeyIsWrittenTheSkillGetsItsValue() {
        Tree tree = build("Set");
        assertEquals(NodeStatus.RUNNING, tree.tickRoot());
        assertEquals("MoveBase", skills.last().name());
        assertEquals(Map.of("max_speed", 0.8, "goal", "ward-4B"), skills.last().inAttributes());
        assertEquals(List.of(), problems);
        assertNoPlaceholderSent();
    }

    @Test
    public void aKeyOfTheTreeItselfSaysNothingWroteIt() {
        Tree tree = build("Local");
        assertEquals(NodeStatus.FAILURE, tree.tickRoot());
        assertEquals(List.of("Local/drive: skill MoveBase not pushed: port goal=\"{target}\" reads blackboard key "
                + "'target', which has no value (nothing has written it)"), problems);
        assertTrue(skills.requests.isEmpty());
    }

    @Test
    public void aDeclaredOutputPortIsWrittenByTheSkillNotSent() {
        Tree tree = build("Detect");
        assertEquals(NodeStatus.RUNNING, tree.tickRoot());
        assertEquals(new SkillRequest("Detect", Map.of("where", "table")), skills.last());
        skills.results.get(0).complete(new SkillResult(SkillResult.Outcome.SUCCESS, null, Map.of("found", "cup")));
        assertEquals(NodeStatus.RUNNING, tree.tickRoot());
        // Grasp's object is not declared: an input, read once Detect has written it
        assertEquals(new SkillRequest("Grasp", Map.of("object", "cup")), skills.last());
        assertEquals(List.of(), problems);
    }

    /**
     * SetBlackboard copying a key without a value: BT.CPP 3's getInput fails and the node throws;
     * BT.CPP 4.8 returns FAILURE when the entry exists (every {key} port creates one when the tree
     * is built), which the oracle case missing-key-copy checks against the real library.
     */
    @Test
    public void setBlackboardFromAKeyWithoutValue() {
        Tree tree = build("Copy");
        String line = "Copy/copy: port value=\"{nowhere}\" reads blackboard key 'nowhere', which has no value "
                + "(nothing has written it)";
        if (version == 4) {
            assertEquals(NodeStatus.FAILURE, tree.tickRoot());
            assertEquals(List.of(line), problems);
            assertEquals(Optional.empty(), tree.blackboard().get("copied"));
            return;
        }
        try {
            tree.tickRoot();
            fail("a version-3 SetBlackboard throws on a missing value");
        } catch (BtRuntimeException expected) {
            assertEquals(line, expected.getMessage());
        }
    }

    private void assertNoPlaceholderSent() {
        assertFalse(skills.requests.isEmpty());
        for (SkillRequest request : skills.requests) {
            request.inAttributes().forEach((port, value) -> assertFalse(request + " sends a blackboard reference",
                    String.valueOf(value).matches("\\$?\\{.*\\}")));
        }
    }
}
