package org.miron.generator;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.Variable;

/**
 * MiniZinc names (fixed by docs/generators.md and docs/io-json.md; the engine and the tests rely
 * on them): context_&lt;ns&gt;_&lt;name&gt;, metric_&lt;ns&gt;_&lt;name&gt;, &lt;vp&gt;_var...
 * ns is the RoQME model's namespace (dots become underscores), omitted when empty.
 */
public final class Names {
    private Names() {
    }

    /** The namespace of the model declaring an element, or "" when it has none. */
    public static String namespace(EObject element) {
        RoqmeModel model = EcoreUtil2.getContainerOfType(element, RoqmeModel.class);
        String ns = model == null ? null : model.getNamespace();
        return ns == null ? "" : ns.trim();
    }

    private static String qualified(Variable variable) {
        String ns = namespace(variable).replace('.', '_');
        return ns.isEmpty() ? variable.getName() : ns + "_" + variable.getName();
    }

    public static String metric(Property property) {
        return "metric_" + qualified(property);
    }

    public static String weight(Property property) {
        return "weight_" + qualified(property);
    }

    public static String context(Context context) {
        return "context_" + qualified(context);
    }

    public static String known(Context context) {
        return context(context) + "_known";
    }

    /**
     * The parameter that keeps (true) or drops (false) the rule of this priority (1 = the first
     * declared, the most important): the engine drops rules that conflict with higher ones.
     */
    public static String keep(int priority) {
        return "miron_keep_" + priority;
    }

    public static String utility(String varpoint, Property property) {
        return varpoint + "_y_" + qualified(property);
    }
}
