package org.miron.dsl;

import org.eclipse.emf.ecore.EPackage;
import org.miron.bt.BtStandaloneSetup;
import org.miron.dsl.roqme.RoqmePackage;

import com.google.inject.Injector;

/** Standalone (non-Eclipse) set-up of the RoQME language. */
public class RoqmeStandaloneSetup extends RoqmeStandaloneSetupGenerated {

    private static Injector injector; // guarded by the class

    /** One injector per process, registrations repeated on every call (see BtStandaloneSetup). */
    public static synchronized Injector doSetup() {
        if (injector == null) {
            injector = new RoqmeStandaloneSetup().createInjectorAndDoEMFRegistration();
        } else {
            EPackage.Registry.INSTANCE.putIfAbsent(RoqmePackage.eNS_URI, RoqmePackage.eINSTANCE);
            BtStandaloneSetup.doSetup();
            new RoqmeStandaloneSetup().register(injector);
        }
        return injector;
    }

    @Override
    public Injector createInjectorAndDoEMFRegistration() {
        // The grammar imports roqme.ecore instead of generating it, so the generated set-up does
        // not register the EPackage; without it the grammar's proxies stay unresolved.
        EPackage.Registry.INSTANCE.putIfAbsent(RoqmePackage.eNS_URI, RoqmePackage.eINSTANCE);
        // RoQME files may sit next to BT files that MIRoN models import: keep .bt loadable.
        BtStandaloneSetup.doSetup();
        return super.createInjectorAndDoEMFRegistration();
    }
}
