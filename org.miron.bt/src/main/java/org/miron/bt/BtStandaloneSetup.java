package org.miron.bt;

import org.eclipse.emf.ecore.EPackage;
import org.miron.bt.bt.BtPackage;

import com.google.inject.Injector;

/** Standalone (non-Eclipse) set-up of the BT language. */
public class BtStandaloneSetup extends BtStandaloneSetupGenerated {

    public static Injector doSetup() {
        return new BtStandaloneSetup().createInjectorAndDoEMFRegistration();
    }

    @Override
    public Injector createInjectorAndDoEMFRegistration() {
        // The grammar imports bt.ecore instead of generating it, so the generated set-up does not
        // register the EPackage; without it the grammar's proxies to bt.ecore stay unresolved.
        EPackage.Registry.INSTANCE.putIfAbsent(BtPackage.eNS_URI, BtPackage.eINSTANCE);
        return super.createInjectorAndDoEMFRegistration();
    }
}
