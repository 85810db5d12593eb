package org.miron.runtime.sim;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import org.miron.executor.ActionRegistry;
import org.miron.executor.Tree;
import org.miron.executor.TreeBuilder;
import org.miron.executor.TreeContext;
import org.miron.executor.UnregisteredActionStrategy;
import org.miron.executor.skills.SkillActionStrategy;
import org.miron.executor.skills.SkillClient;
import org.miron.executor.skills.VariantSource;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * What every run of a simulation shares, read once: the engine's io.json, the RoQME runtime model,
 * the woven tree, the checked world and, when the model states requirements, what their monitors
 * read (null: none are checked).
 */
public record Setup(IoModel io, RoqmeModel roqme, Path tree, WorldModel world, RequirementModel requirements) {
    private static final Object TREES = new Object();

    public Setup(IoModel io, RoqmeModel roqme, Path tree, WorldModel world) {
        this(io, roqme, tree, world, null);
    }

    /** Builds a tree whose actions are pushed to {@code skills}; the BT language is loaded one tree at a time. */
    static Tree buildTree(Path tree, TreeContext context, VariantSource variants, UnregisteredActionStrategy skills) {
        synchronized (TREES) {
            ActionRegistry registry = new ActionRegistry();
            registry.registerVariantAction(variants).setFallback(skills);
            return new TreeBuilder(registry, context).build(tree);
        }
    }

    /** The skills a tree pushes with their ports, and the contexts a RoQME model receives: what a world is checked against. */
    public static WorldEnv env(Path tree, RoqmeModel roqme) {
        Map<String, Set<String>> skills = new LinkedHashMap<>();
        SkillClient none = request -> {
            throw new IllegalStateException("not running");
        };
        SkillActionStrategy pushing = new SkillActionStrategy(none);
        buildTree(tree, new TreeContext(), new VariantSource(), spec -> {
            skills.computeIfAbsent(spec.id(), k -> new LinkedHashSet<>()).addAll(spec.info().ports().attributes().keySet());
            return pushing.create(spec);
        });
        skills.values().forEach(ports -> {
            ports.remove("ID");
            ports.remove("name");
        });
        Map<String, RoqmeModel.Type> contexts = new LinkedHashMap<>();
        for (RoqmeModel.Variable v : roqme.contexts()) {
            if (v.derived() == null || v.derived().isNull()) {
                contexts.put(v.name(), v.type());
            }
        }
        return new WorldEnv(skills, contexts);
    }
}
