package org.miron.bt.util;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.miron.bt.bt.BTModel;

/** The BehaviorTree.CPP version a file is written for, from its root's BTCPP_format attribute. */
public final class BtFormats {
    /** Files without BTCPP_format: the format of BehaviorTree.CPP 3, MIRoN's default. */
    public static final int DEFAULT_VERSION = 3;
    /** The attribute of {@code <root>} that names the format. */
    public static final String ATTRIBUTE = "BTCPP_format";

    private BtFormats() {
    }

    /** 3 without BTCPP_format, else its integer value; 0 for a value that is not an integer. */
    public static int version(BTModel model) {
        String format = model.getBTCPP_format();
        if (format == null) {
            return DEFAULT_VERSION;
        }
        try {
            return Integer.parseInt(format.trim());
        } catch (NumberFormatException e) {
            return 0;
        }
    }

    /** The version of the file an element belongs to (the default for an element outside a file). */
    public static int versionOf(EObject element) {
        BTModel model = EcoreUtil2.getContainerOfType(element, BTModel.class);
        return model == null ? DEFAULT_VERSION : version(model);
    }
}
