package org.miron.cli;

import java.io.File;
import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.util.Imports;
import org.miron.generator.standalone.ModelLoader;

/**
 * How a MIRoN model names its RoQME inputs: {@code roqme.safety} where the model imports its RoQME
 * part {@code as roqme}, so that reports and the live page use the model's words, not the engine's
 * parameters ({@code metric_Intralogistics_safety}) nor the bare RoQME names.
 */
public final class ModelNames {
    private final Map<String, String> aliases = new LinkedHashMap<>();

    private ModelNames() {
    }

    /** The names of a model; a file that does not load names inputs by their RoQME names. */
    public static ModelNames of(File miron) {
        ModelNames names = new ModelNames();
        try {
            Resource resource = new ModelLoader().load(miron);
            if (!resource.getContents().isEmpty() && resource.getContents().get(0) instanceof RoqmeModel model) {
                for (Import imp : model.getImports()) {
                    String alias = Imports.aliasOf(imp);
                    Resource imported = Imports.load(imp);
                    if (alias != null && imported != null && !imported.getContents().isEmpty()
                            && imported.getContents().get(0) instanceof RoqmeModel roqme && roqme.getNamespace() != null) {
                        names.aliases.putIfAbsent(roqme.getNamespace(), alias);
                    }
                }
            }
        } catch (RuntimeException unreadable) {
            // the demo has generated it already; names fall back to the RoQME ones
        }
        return names;
    }

    /** No model: every input by its RoQME name. */
    public static ModelNames none() {
        return new ModelNames();
    }

    /** {@code Intralogistics}, {@code safety} → {@code roqme.safety} (or {@code safety} without an alias). */
    public String input(String namespace, String name) {
        String alias = aliases.get(namespace);
        return alias == null ? name : alias + "." + name;
    }

    /**
     * An engine parameter as the model says it: {@code metric_Intralogistics_safety} → {@code roqme.safety},
     * {@code context_Hospital_shift} → {@code qos.shift}; other parameters unchanged.
     */
    public String parameter(String param) {
        for (String kind : new String[] { "metric_", "context_" }) {
            if (param.startsWith(kind)) {
                String rest = param.substring(kind.length());
                for (Map.Entry<String, String> alias : aliases.entrySet()) {
                    if (rest.startsWith(alias.getKey() + "_")) {
                        return alias.getValue() + "." + rest.substring(alias.getKey().length() + 1);
                    }
                }
                int underscore = rest.indexOf('_');
                return underscore > 0 && Character.isUpperCase(rest.charAt(0)) ? rest.substring(underscore + 1) : rest;
            }
        }
        return param;
    }

    /** For the live page: "namespace/name" → the model's name. */
    public String qualified(String namespaceAndName) {
        int slash = namespaceAndName.indexOf('/');
        return input(namespaceAndName.substring(0, slash), namespaceAndName.substring(slash + 1));
    }
}
