package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.junit.Test;
import org.miron.dsl.RoqmeStandaloneSetup;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.roqme.RoqmePackage;

import com.google.inject.Injector;

/** What the `miron check` CLI relies on: every extension has its services after the set-ups. */
public class LanguageSetupTest {

    @Test
    public void everyExtensionIsRegistered() {
        Models.injector();
        Injector roqme = RoqmeStandaloneSetup.doSetup();
        assertNotNull(roqme);
        for (String ext : new String[] { "roqme", "miron", "bt" }) {
            assertNotNull(ext, IResourceServiceProvider.Registry.INSTANCE
                    .getResourceServiceProvider(URI.createFileURI("/tmp/x." + ext)));
        }
        assertTrue(EPackage.Registry.INSTANCE.get(RoqmePackage.eNS_URI) != null);
        assertTrue(EPackage.Registry.INSTANCE.get(MironPackage.eNS_URI) != null);
    }

    @Test
    public void enumLiteralsAndVariablesSplitAlike() {
        IQualifiedNameConverter converter = Models.injector().getInstance(IQualifiedNameConverter.class);
        assertEquals(QualifiedName.create("roqme", "AvailableSpace", "HIGH"),
                converter.toQualifiedName("roqme::AvailableSpace::HIGH"));
        assertEquals(QualifiedName.create("roqme", "safety"), converter.toQualifiedName("roqme.safety"));
    }
}
