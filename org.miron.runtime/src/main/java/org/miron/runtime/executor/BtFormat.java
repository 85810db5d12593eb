package org.miron.runtime.executor;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.bt.bt.BTModel;
import org.miron.bt.util.BtFormats;

/** The BehaviorTree.CPP format of the file an element is in: BTCPP_format on its root, 3 when absent. */
final class BtFormat {
    private BtFormat() {
    }

    static int of(EObject object) {
        EObject top = EcoreUtil.getRootContainer(object);
        return top instanceof BTModel model ? BtFormats.version(model) : BtFormats.DEFAULT_VERSION;
    }
}
