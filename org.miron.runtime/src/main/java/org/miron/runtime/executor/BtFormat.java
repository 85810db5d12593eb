package org.miron.runtime.executor;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.bt.bt.BTModel;
import org.miron.bt.util.BtAttributes;

/** The BehaviorTree.CPP format of a file: BTCPP_format on its root element, 3 when absent. */
final class BtFormat {
    private BtFormat() {
    }

    static int of(EObject object) {
        EObject top = EcoreUtil.getRootContainer(object);
        if (top instanceof BTModel model) {
            String format = BtAttributes.value(model.getAttributes(), "BTCPP_format");
            if (format != null && format.trim().equals("4")) {
                return 4;
            }
        }
        return 3;
    }
}
