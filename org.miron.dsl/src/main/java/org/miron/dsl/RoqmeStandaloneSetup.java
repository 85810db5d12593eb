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

    /**
     * Makes an injector already created for RoQME with more bindings (the language server's, with the
     * ide services) the one of this process, unless there is one: the set-ups of the languages that
     * import RoQME then register it instead of creating a second injector (docs/lsp.md, Start-up).
     */
    public static synchronized void adopt(Injector withMoreBindings) {
        if (injector == null) {
            injector = withMoreBindings;
        }
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
