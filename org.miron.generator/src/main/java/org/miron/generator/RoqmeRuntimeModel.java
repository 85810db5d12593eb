package org.miron.generator;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.dsl.roqme.RoqmeModel;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Writes name.roqme.json, what the RoQME QoS Metrics Provider runs (docs/roqme-model.md, schema
 * docs/roqme-model.schema.json): the contexts, params, vars, timers, beliefs and observations of a
 * .roqme file, or of the RoQME part of a .miron file, with those of every file it imports. A
 * model with anything the runtime model cannot represent gets errors with the codes below and no
 * file at all.
 */
public final class RoqmeRuntimeModel {
    /** Appended to the model's base name. */
    public static final String SUFFIX = ".roqme.json";

    /** A timer whose period is not a time literal or schedule("cron"). */
    public static final String TIMER_PERIOD = "roqme.unsupported-timer-period";
    /** An observation reading (or an enum literal of) a MIRoN varpoint. */
    public static final String VARPOINT = "roqme.unsupported-varpoint";
    /** A reference to something that is not a declaration of the runtime model. */
    public static final String REFERENCE = "roqme.unsupported-reference";
    /** Two declarations that neither name nor namespace tell apart. */
    public static final String NAME_CLASH = "roqme.unsupported-name-clash";
    /** An expression class the generator has no case for. */
    public static final String EXPRESSION = "roqme.unsupported-expression";
    /** A declaration, action or type class the generator has no case for. */
    public static final String ELEMENT = "roqme.unsupported-element";

    private RoqmeRuntimeModel() {
    }

    /**
     * Generates the runtime model of input (a .roqme or .miron resource without syntax or linking
     * errors) into files as name.roqme.json; on a problem adds errors and generates nothing.
     */
    public static void stage(Resource input, StagedFiles files, List<GenerationError> errors) {
        if (input.getContents().isEmpty() || !(input.getContents().get(0) instanceof RoqmeModel model)) {
            return;
        }
        String name = input.getURI().trimFileExtension().lastSegment();
        List<GenerationError> found = new ArrayList<>();
        ObjectNode root = tree(model, name, input.getURI().lastSegment(), found);
        errors.addAll(found);
        if (!found.isEmpty()) {
            return;
        }
        files.generateFile(name + SUFFIX, RoqmeJsonText.print(root));
    }

    /** The runtime model as a JSON tree; problems go to errors (the tree is then incomplete). */
    static ObjectNode tree(RoqmeModel model, String name, String source, List<GenerationError> errors) {
        ObjectNode root = JsonNodeFactory.instance.objectNode();
        root.put("format", 1);
        root.put("model", name);
        root.put("source", source);
        RoqmeDeclarations declarations = RoqmeDeclarations.of(model, errors);
        RoqmeDeclarationJson writer = new RoqmeDeclarationJson(root, declarations, errors);
        declarations.all.forEach(writer::doSwitch);
        return root;
    }
}
