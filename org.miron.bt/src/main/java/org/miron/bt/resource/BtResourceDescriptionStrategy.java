package org.miron.bt.resource;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.impl.DefaultResourceDescriptionStrategy;
import org.eclipse.xtext.util.IAcceptor;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.util.BtTrees;

/**
 * Exports what the default strategy exports, except a tree that repeats an earlier tree of its
 * file with the same ID and content (BehaviorTree.CPP keeps the first): files that refer to the
 * ID, such as a .miron binding, then see one tree instead of an ambiguous pair. A repeated ID with
 * different content stays exported twice, and so ambiguous, as the BT validator reports it.
 */
public class BtResourceDescriptionStrategy extends DefaultResourceDescriptionStrategy {

    @Override
    public boolean createEObjectDescriptions(EObject eObject, IAcceptor<IEObjectDescription> acceptor) {
        if (eObject instanceof BehaviorTree tree && repeatsAnEarlierTree(tree)) {
            return false;
        }
        return super.createEObjectDescriptions(eObject, acceptor);
    }

    private static boolean repeatsAnEarlierTree(BehaviorTree tree) {
        if (tree.getName() == null || !(tree.eContainer() instanceof BTModel model)) {
            return false;
        }
        for (BehaviorTree other : model.getTrees()) {
            if (other == tree) {
                return false;
            }
            if (tree.getName().equals(other.getName()) && BtTrees.sameContent(tree, other)) {
                return true;
            }
        }
        return false;
    }
}
