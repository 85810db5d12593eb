package org.miron.dsl.ide.hover;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.dsl.roqme.Action;
import org.miron.dsl.roqme.BeliefVariable;
import org.miron.dsl.roqme.Clears;
import org.miron.dsl.roqme.EvidenceAction;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.Sentence;
import org.miron.dsl.roqme.Undermines;
import org.miron.dsl.util.Evidence;

/**
 * What the RoQME reasoner makes of a model, for hovers (markdown): per observation action its
 * likelihood ratio and survival; per belief its reference, survival and the observations that
 * move it. The numbers come from {@link Evidence}, as the provider computes them.
 */
final class EvidenceHover {

    private EvidenceHover() {
    }

    /** Each action of the observation: evidence with ratio and survival, or what it does. */
    static String observation(Observation observation) {
        StringBuilder text = new StringBuilder("**observation " + observation.getName() + "** when it fires:");
        for (Action action : observation.getActions()) {
            text.append("\n- ");
            if (action instanceof EvidenceAction evidence) {
                text.append(evidence(evidence, name(evidence.getBelief())));
                text.append(", survival ").append(survival(evidence));
            } else if (action instanceof Clears clears) {
                text.append("clears `").append(name(clears.getBelief())).append("` (drops its evidence)");
            } else {
                text.append('`').append(DslDocumentationProvider.sourceText(action)).append('`');
            }
        }
        return text.toString();
    }

    /** Reference, survival and the observations (of every model loaded with this one) that move the belief. */
    static String belief(BeliefVariable belief) {
        String kind = belief.eClass() == RoqmePackage.Literals.BELIEF_VARIABLE ? "beliefvar" : "property";
        StringBuilder text = new StringBuilder("**" + kind + " " + belief.getName() + "**: reference ");
        text.append(Evidence.number(Evidence.reference(belief)));
        if (belief.getReference() == null) {
            text.append(" (the default)");
        }
        text.append(", evidence survives ");
        text.append(belief.getSurvival() == null ? Evidence.describe(Evidence.DEFAULT_SURVIVAL_MS) + " (the default)"
                : Evidence.describe(Evidence.exactMillis(belief.getSurvival())));
        text.append(" unless an observation says otherwise");
        List<String> movers = movers(belief);
        if (movers.isEmpty()) {
            text.append("\n\nNo observation moves it: its estimate stays at its reference.");
        } else {
            text.append("\n\nMoved by:");
            movers.forEach(m -> text.append("\n- ").append(m));
        }
        return text.toString();
    }

    private static List<String> movers(BeliefVariable belief) {
        URI target = EcoreUtil.getURI(belief);
        Resource home = belief.eResource();
        List<Resource> resources = home.getResourceSet() == null ? List.of(home) : home.getResourceSet().getResources();
        List<String> movers = new ArrayList<>();
        for (Resource resource : List.copyOf(resources)) {
            if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof RoqmeModel model)) {
                continue;
            }
            String where = resource == home ? "" : " (" + resource.getURI().lastSegment() + ")";
            for (Sentence sentence : model.getSentences()) {
                if (!(sentence instanceof Observation observation)) {
                    continue;
                }
                for (Action action : observation.getActions()) {
                    String line = mover(action, target);
                    if (line != null) {
                        movers.add("`" + observation.getName() + "`" + where + ": " + line);
                    }
                }
            }
        }
        return movers;
    }

    /** How action moves the belief at target, or null when it does not touch it. */
    private static String mover(Action action, URI target) {
        if (action instanceof EvidenceAction evidence
                && refersTo(action, RoqmePackage.Literals.EVIDENCE_ACTION__BELIEF, target)) {
            return evidence(evidence, null) + ", survival " + survival(evidence);
        }
        if (action instanceof Clears && refersTo(action, RoqmePackage.Literals.CLEARS__BELIEF, target)) {
            return "clears its evidence";
        }
        return null;
    }

    /** Compares without resolving: hovering must not load every file other models mention. */
    private static boolean refersTo(EObject action, org.eclipse.emf.ecore.EReference feature, URI target) {
        Object value = action.eGet(feature, false);
        return value instanceof EObject ref && target.equals(EcoreUtil.getURI(ref));
    }

    /** "undermines `safety` HIGH: likelihood ratio 3.333". */
    private static String evidence(EvidenceAction action, String beliefName) {
        String verb = action instanceof Undermines ? "undermines" : "reinforces";
        return verb + (beliefName == null ? "" : " `" + beliefName + "`") + " " + Evidence.strength(action.getStrength()).name()
                + ": likelihood ratio " + Evidence.number(Evidence.ratio(action));
    }

    /** The action's survival and where it comes from. */
    private static String survival(EvidenceAction action) {
        String time = Evidence.describe(Evidence.survivalMs(action));
        if (action.getSurvival() != null) {
            return time;
        }
        BeliefVariable belief = action.getBelief();
        return belief != null && !belief.eIsProxy() && belief.getSurvival() != null ? time + " (of " + belief.getName() + ")"
                : time + " (the default)";
    }

    private static String name(BeliefVariable belief) {
        return belief == null || belief.eIsProxy() ? "?" : belief.getName();
    }
}
