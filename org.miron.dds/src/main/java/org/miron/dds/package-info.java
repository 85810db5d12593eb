/**
 * The DDS / ROS 2 bridge ({@code miron dds-bridge}, docs/dds.md): {@link org.miron.dds.Bridge} joins a
 * DDS domain and the MIRoN bus. ROS 2 topics and RoQME's DDS context topics become
 * {@code roqme.context} ({@code ContextConversion}); {@code miron.decision} and {@code roqme.estimate}
 * become ROS 2 topics and {@code RoqmeEstimate}. Bad samples are counted, logged and dropped.
 */
package org.miron.dds;
