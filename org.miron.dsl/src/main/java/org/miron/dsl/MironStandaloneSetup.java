package org.miron.dsl;

import org.eclipse.emf.ecore.EPackage;
import org.miron.bt.BtStandaloneSetup;
import org.miron.bt.bt.BtPackage;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.roqme.RoqmePackage;

import com.google.inject.Injector;

/**
 * Standalone set-up of the MIRoN language. It also sets up RoQME and BT, so that the .roqme and
 * .bt files a MIRoN model imports load with their own languages.
 */
public class MironStandaloneSetup extends MironStandaloneSetupGenerated {

    private static Injector injector; // guarded by the class

    /** One injector per process, registrations repeated on every call (see BtStandaloneSetup). */
    public static synchronized Injector doSetup() {
        if (injector == null) {
            injector = new MironStandaloneSetup().createInjectorAndDoEMFRegistration();
        } else {
            EPackage.Registry.INSTANCE.putIfAbsent(MironPackage.eNS_URI, MironPackage.eINSTANCE);
            RoqmeStandaloneSetup.doSetup();
            BtStandaloneSetup.doSetup();
            new MironStandaloneSetup().register(injector);
        }
        return injector;
    }

    @Override
    public Injector createInjectorAndDoEMFRegistration() {
        EPackage.Registry.INSTANCE.putIfAbsent(BtPackage.eNS_URI, BtPackage.eINSTANCE);
        EPackage.Registry.INSTANCE.putIfAbsent(RoqmePackage.eNS_URI, RoqmePackage.eINSTANCE);
        EPackage.Registry.INSTANCE.putIfAbsent(MironPackage.eNS_URI, MironPackage.eINSTANCE);
        BtStandaloneSetup.doSetup();
        return super.createInjectorAndDoEMFRegistration();
    }
}
