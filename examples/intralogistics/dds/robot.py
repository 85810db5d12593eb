#!/usr/bin/env python3
"""A stand-in for a ROS 2 robot in the intralogistics loop, written with Cyclone DDS (PyPI
cyclonedds 11.0.1), an implementation independent of the bridge's: it speaks ROS 2's conventions
(topic rt/<name>, type pkg::msg::dds_::Name_) with no ROS 2 installed.

It publishes sensor_msgs/BatteryState on battery_state, draining from --start by --step every
--period seconds, and prints every decision the bridge publishes on miron/task (std_msgs/String,
transient-local: it gets the current one at once), miron/max_velocity (std_msgs/Float64) and
speed_limit (nav2_msgs/SpeedLimit, declared here from its field list, as Nav2's controller reads it):

    task: pickDeliverCharge
    speed_limit: 0.72 m/s
    battery: 0.30
    ...
    task: dock

With --until VALUE it exits 0 once miron/task says VALUE, 1 after --timeout seconds. Run beside the
broker, the RoQME provider, the engine and `miron dds-bridge --config examples/intralogistics/dds/bridge.json`
(docs/dds.md, "Running the loop with a ROS 2 robot"). DdsScenarios.exampleRobotClosesTheLoop runs it.

Cyclone's network: CYCLONEDDS_URI when set; otherwise the loopback interface, with 127.0.0.1 as a
unicast peer (the bridge binds 127.0.0.1 by default, and lo usually has no multicast).
"""
import argparse
import os
import sys
import time
from dataclasses import dataclass, field

if "CYCLONEDDS_URI" not in os.environ:
    os.environ["CYCLONEDDS_URI"] = ("<CycloneDDS><Domain id=\"any\"><General><Interfaces>"
                                    "<NetworkInterface name=\"lo\"/></Interfaces></General>"
                                    "<Discovery><Peers><Peer Address=\"127.0.0.1\"/></Peers>"
                                    "<SPDPInterval>1s</SPDPInterval></Discovery></Domain></CycloneDDS>")

from cyclonedds.core import Policy, Qos  # noqa: E402 (after the environment is set)
from cyclonedds.domain import DomainParticipant  # noqa: E402
from cyclonedds.idl import IdlStruct  # noqa: E402
import cyclonedds.idl.annotations as annotate  # noqa: E402
import cyclonedds.idl.types as t  # noqa: E402
from cyclonedds.pub import DataWriter  # noqa: E402
from cyclonedds.sub import DataReader  # noqa: E402
from cyclonedds.topic import Topic  # noqa: E402
from cyclonedds.util import duration  # noqa: E402


@dataclass
@annotate.final
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: t.int32 = 0
    nanosec: t.uint32 = 0


@dataclass
@annotate.final
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time = field(default_factory=Time)
    frame_id: str = ""


@dataclass
@annotate.final
class BatteryState(IdlStruct, typename="sensor_msgs::msg::dds_::BatteryState_"):
    header: Header = field(default_factory=Header)
    voltage: t.float32 = 0.0
    temperature: t.float32 = 0.0
    current: t.float32 = 0.0
    charge: t.float32 = 0.0
    capacity: t.float32 = 0.0
    design_capacity: t.float32 = 0.0
    percentage: t.float32 = 0.0
    power_supply_status: t.uint8 = 0
    power_supply_health: t.uint8 = 0
    power_supply_technology: t.uint8 = 0
    present: bool = False
    cell_voltage: t.sequence[t.float32] = field(default_factory=list)
    cell_temperature: t.sequence[t.float32] = field(default_factory=list)
    location: str = ""
    serial_number: str = ""


@dataclass
@annotate.final
class String(IdlStruct, typename="std_msgs::msg::dds_::String_"):
    data: str = ""


@dataclass
@annotate.final
class Float64(IdlStruct, typename="std_msgs::msg::dds_::Float64_"):
    data: t.float64 = 0.0


@dataclass
@annotate.final
class SpeedLimit(IdlStruct, typename="nav2_msgs::msg::dds_::SpeedLimit_"):
    header: Header = field(default_factory=Header)
    percentage: bool = False
    speed_limit: t.float64 = 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--domain", type=int, default=0, help="the DDS domain (ROS_DOMAIN_ID), 0")
    ap.add_argument("--start", type=float, default=0.9, help="the first battery percentage, 0..1 (0.9)")
    ap.add_argument("--step", type=float, default=0.1, help="how much it drains per period (0.1)")
    ap.add_argument("--period", type=float, default=1.0, help="seconds between battery samples (1)")
    ap.add_argument("--until", help="exit 0 once miron/task says this (e.g. dock)")
    ap.add_argument("--timeout", type=float, default=0, help="with --until: give up after this many seconds (0: never)")
    a = ap.parse_args()

    dp = DomainParticipant(a.domain)
    battery = DataWriter(dp, Topic(dp, "rt/battery_state", BatteryState),
                         qos=Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(1)))
    latched = Qos(Policy.Reliability.Reliable(duration(seconds=1)), Policy.Durability.TransientLocal,
                  Policy.History.KeepLast(1))
    task = DataReader(dp, Topic(dp, "rt/miron/task", String), qos=latched)
    velocity = DataReader(dp, Topic(dp, "rt/miron/max_velocity", Float64), qos=latched)
    speed_limit = DataReader(dp, Topic(dp, "rt/speed_limit", SpeedLimit), qos=latched)

    level, next_sample = a.start, time.monotonic()
    end = time.monotonic() + a.timeout if a.until and a.timeout > 0 else None
    while end is None or time.monotonic() < end:
        if time.monotonic() >= next_sample:
            battery.write(BatteryState(header=Header(frame_id="base_link"), percentage=level, present=True))
            print("battery: %.2f" % level, flush=True)
            level, next_sample = max(0.0, level - a.step), next_sample + a.period
        for s in velocity.take(N=16):
            if isinstance(s, Float64):
                print("maxVelocity: %g" % s.data, flush=True)
        for s in speed_limit.take(N=16):
            if isinstance(s, SpeedLimit):
                print("speed_limit: %g %s" % (s.speed_limit, "%" if s.percentage else "m/s"), flush=True)
        for s in task.take(N=16):
            if isinstance(s, String):  # not an InvalidSample (the bridge went away)
                print("task: " + s.data, flush=True)
                if a.until is not None and s.data == a.until:
                    return 0
        time.sleep(0.05)
    print("no task %s within %g s" % (a.until, a.timeout), file=sys.stderr, flush=True)
    return 1


if __name__ == "__main__":
    sys.exit(main())
