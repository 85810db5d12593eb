/**
 * The test kit's runtime part (configuration {@code runtimeKit}): broker, skill mock, bus probe and
 * engine on fresh loopback ports, and the small test models, for org.miron.runtime's tests and the
 * CLI's process tests. Compiled against org.miron.runtime, which its users already depend on.
 */
package org.miron.testkit.runtime;
