/**
 * A robot's own message types, read from ROS 2 message packages at start-up (issue 38): no ROS 2
 * installation and no generated code. {@link org.miron.dds.types.MsgParser} (.msg) and
 * {@link org.miron.dds.types.IdlParser} (rosidl's .idl) read definitions into the type model
 * ({@link org.miron.dds.types.MsgType}, {@link org.miron.dds.types.MsgField},
 * {@link org.miron.dds.types.FieldType}); {@link org.miron.dds.types.MessagePackages} loads package
 * folders; {@link org.miron.dds.types.TypeRegistry} resolves nested names and gives defaults;
 * {@link org.miron.dds.types.CdrWriter} writes XCDR1 as ROS 2's DDS layers do and
 * {@link org.miron.dds.types.CdrReader} reads XCDR1 and XCDR2. Nothing here names the DDS library:
 * the transport wraps these types for it ({@code DefinedType}). Why a parser of our own: no .msg
 * parser is published on Maven Central, and the IDL compilers there generate code, which the issue
 * rules out.
 */
package org.miron.dds.types;
