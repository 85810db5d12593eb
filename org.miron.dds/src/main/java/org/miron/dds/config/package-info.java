/**
 * The bridge's configuration (docs/dds-bridge.schema.json): {@link org.miron.dds.config.ConfigReader}
 * checks it against the message types and reports the first problem with its line, column and JSON
 * pointer ({@code Located} keeps the positions Jackson's trees forget).
 */
package org.miron.dds.config;
