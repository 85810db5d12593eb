/** The runtime model {@code name.roqme.json} (format 1) as Jackson records; the contract is docs/roqme-model.md. */
package org.miron.runtime.roqme.model;
