package org.miron.bt;

import org.eclipse.emf.ecore.EPackage;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.resource.BtXmlFiles;

import com.google.inject.Injector;

/** Standalone (non-Eclipse) set-up of the BT language. */
public class BtStandaloneSetup extends BtStandaloneSetupGenerated {

    private static Injector injector; // guarded by the class

    /**
     * One injector per process: creating one costs a noticeable part of a CLI run, and the RoQME
     * and MIRoN set-ups ask for BT too. The registrations are repeated (cheap) on every call, as
     * tests may restore EMF's global registries in between.
     */
    public static synchronized Injector doSetup() {
        if (injector == null) {
            injector = new BtStandaloneSetup().createInjectorAndDoEMFRegistration();
        } else {
            EPackage.Registry.INSTANCE.putIfAbsent(BtPackage.eNS_URI, BtPackage.eINSTANCE);
            new BtStandaloneSetup().register(injector);
        }
        return injector;
    }

    /**
     * Makes an injector already created for BT with more bindings (the language server's, with the
     * ide services) the one of this process, unless there is one: the set-ups of the languages that
     * import BT then register it instead of creating a second injector (docs/lsp.md, Start-up).
     */
    public static synchronized void adopt(Injector withMoreBindings) {
        if (injector == null) {
            injector = withMoreBindings;
        }
    }

    @Override
    public Injector createInjectorAndDoEMFRegistration() {
        // The grammar imports bt.ecore instead of generating it, so the generated set-up does not
        // register the EPackage; without it the grammar's proxies to bt.ecore stay unresolved.
        EPackage.Registry.INSTANCE.putIfAbsent(BtPackage.eNS_URI, BtPackage.eINSTANCE);
        return super.createInjectorAndDoEMFRegistration();
    }

    /** Also .xml, for BehaviorTree.CPP files (content-aware, see BtXmlFiles). */
    @Override
    public void register(Injector injector) {
        super.register(injector);
        BtXmlFiles.register(injector);
    }
}
