package org.miron.gradle;

/**
 * The core's languages are set up in statics of this plugin's class loader (EMF's package
 * registry, the languages' injectors), which Gradle shares between the projects of a build that take
 * the plugin from the same class path: under --parallel, checkMiron and generateMiron of different
 * projects take turns rather than set them up at the same time.
 */
final class CoreLock {
    static final Object LOCK = new Object();

    private CoreLock() {
    }
}
