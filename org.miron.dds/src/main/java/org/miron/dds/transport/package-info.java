/**
 * DDS behind an interface of ours: {@link org.miron.dds.transport.DdsTransport} (readers and writers
 * of messages as JSON trees) and its one implementation on IHMC's ROS 2 library,
 * {@link org.miron.dds.transport.IhmcTransport}. The library has one upstream, last released in 2024:
 * nothing outside this package names it. {@code JsonOut}/{@code JsonIn} convert any message type it
 * ships through its generic serializer; {@code RoqmeType} is RoQME's own IDL, keyed by name or not;
 * {@code DefinedType} carries a type read from a message package (org.miron.dds.types), encoded by
 * our CDR writer and reader straight into the library's payload;
 * {@code NativeKeySwitch} makes a keyed topic possible at all with this version of the library
 * (docs/dds.md, "Keyed RoQME topics").
 */
package org.miron.dds.transport;
