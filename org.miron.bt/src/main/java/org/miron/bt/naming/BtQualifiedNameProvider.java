package org.miron.bt.naming;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.TreeNode;

/**
 * Trees are named by their ID and nodes by their {@code name} attribute, both unqualified: BT
 * files have no namespaces, and MIRoN refers to them through its import alias ({@code main.Charge}).
 * Attributes are not named elements even though they have a {@code name} feature.
 */
public class BtQualifiedNameProvider extends IQualifiedNameProvider.AbstractImpl {

    @Override
    public QualifiedName getFullyQualifiedName(EObject obj) {
        String name = null;
        if (obj instanceof BehaviorTree) {
            name = ((BehaviorTree) obj).getName();
        } else if (obj instanceof TreeNode) {
            name = ((TreeNode) obj).getName();
        }
        return name == null || name.isEmpty() ? null : QualifiedName.create(name);
    }
}
