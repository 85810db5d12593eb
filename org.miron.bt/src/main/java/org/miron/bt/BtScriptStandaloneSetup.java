package org.miron.bt;

import org.eclipse.emf.ecore.EPackage;
import org.miron.bt.script.ast.AstPackage;

import com.google.inject.Injector;

/** Standalone set-up of the BehaviorTree.CPP 4 scripting language (see org.miron.bt.script). */
public class BtScriptStandaloneSetup extends BtScriptStandaloneSetupGenerated {

    private static Injector injector; // guarded by the class

    /** One injector per process, as for the BT language (BtStandaloneSetup). */
    public static synchronized Injector doSetup() {
        if (injector == null) {
            injector = new BtScriptStandaloneSetup().createInjectorAndDoEMFRegistration();
        } else {
            EPackage.Registry.INSTANCE.putIfAbsent(AstPackage.eNS_URI, AstPackage.eINSTANCE);
            new BtScriptStandaloneSetup().register(injector);
        }
        return injector;
    }

    @Override
    public Injector createInjectorAndDoEMFRegistration() {
        // The grammar imports btscript.ecore, which the generated set-up does not register.
        EPackage.Registry.INSTANCE.putIfAbsent(AstPackage.eNS_URI, AstPackage.eINSTANCE);
        return super.createInjectorAndDoEMFRegistration();
    }
}
