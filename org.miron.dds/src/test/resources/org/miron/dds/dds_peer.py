#!/usr/bin/env python3
"""An independent DDS peer for the bridge's tests: Cyclone DDS (PyPI cyclonedds 11.0.1) speaking
ROS 2's conventions (topics rt/<name>, types pkg::msg::dds_::Name_) and RoQME's own types.

Driven over stdin/stdout, one JSON object per line, so a Java test can play a ROS 2 robot:
  {"op": "writer", "id": "bat", "topic": "rt/battery_state", "type": "sensor_msgs/BatteryState",
   "durability": "volatile|transient_local", "depth": 1, "partition": "..."}
     (RoQME's types are keyed by name as in their IDL; type "unkeyed RoqmeEstimate" is the struct without @key)
  {"op": "reader", ...same fields...}          samples come back as {"event": "sample", "id", "data"}
  {"op": "write", "id": "bat", "data": {...}}   fields not given keep their defaults
  {"op": "dispose", "id": "est", "data": {"name": "safety"}}   disposes that instance (keyed types)
  {"op": "await_matched", "id": "bat", "count": 1, "timeout": 30}
                                               -> {"event": "matched", "id", "count"} or {"event": "timeout", "id", "count"}
  {"op": "close", "id": "bat"}   {"op": "quit"}
  {"op": "encode", "type": "miron_test_msgs/AllKinds", "data": {...}, "xcdr2": false, "appendable": false}
                                               -> {"event": "encoded", "hex": "0001..."} (Cyclone's own CDR of the message)
  {"op": "decode", "type": ..., "hex": "0001...", "appendable": false} -> {"event": "decoded", "data": {...}}
With --codec the peer joins no domain and serves only encode and decode.
The robot's own types (my_robot_msgs/PowerStatus, nav2_msgs/SpeedLimit, miron_test_msgs/AllKinds)
are declared here from their .msg field lists, independently of the bridge's reading of the files.
Every command is answered ({"event": "ok", "op"} at least); errors as {"event": "error", "message"}.
"""
import dataclasses
import json
import sys
import threading
import time
import typing
from dataclasses import dataclass, field

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
import cyclonedds.idl.annotations as annotate
import cyclonedds.idl.types as t
from cyclonedds.pub import DataWriter, Publisher
from cyclonedds.sub import DataReader, Subscriber
from cyclonedds.topic import Topic
from cyclonedds.util import duration


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
class Float32(IdlStruct, typename="std_msgs::msg::dds_::Float32_"):
    data: t.float32 = 0.0


@dataclass
@annotate.final
class Bool(IdlStruct, typename="std_msgs::msg::dds_::Bool_"):
    data: bool = False


@dataclass
@annotate.final
class Int32(IdlStruct, typename="std_msgs::msg::dds_::Int32_"):
    data: t.int32 = 0


# RoQME's own types (module RoqmeDDSTopics), as the original IDL declares them: keyed by name. The
# unkeyed twins below (same type names) stand for peers that declared the structs without @key; DDS
# never matches a keyed topic with an unkeyed one, so each side must choose the same (docs/dds.md).
@dataclass
@annotate.final
class RoqmeDoubleContext(IdlStruct, typename="RoqmeDDSTopics::RoqmeDoubleContext"):
    name: str = ""
    annotate.key("name")
    value: t.sequence[t.float64] = field(default_factory=list)


@dataclass
@annotate.final
class RoqmeIntContext(IdlStruct, typename="RoqmeDDSTopics::RoqmeIntContext"):
    name: str = ""
    annotate.key("name")
    value: t.sequence[t.int64] = field(default_factory=list)


@dataclass
@annotate.final
class RoqmeBoolContext(IdlStruct, typename="RoqmeDDSTopics::RoqmeBoolContext"):
    name: str = ""
    annotate.key("name")
    value: t.sequence[bool] = field(default_factory=list)


@dataclass
@annotate.final
class RoqmeEnumContext(IdlStruct, typename="RoqmeDDSTopics::RoqmeEnumContext"):
    name: str = ""
    annotate.key("name")
    value: t.sequence[str] = field(default_factory=list)


@dataclass
@annotate.final
class RoqmeEventContext(IdlStruct, typename="RoqmeDDSTopics::RoqmeEventContext"):
    name: str = ""
    annotate.key("name")
    value: t.sequence[str] = field(default_factory=list)


@dataclass
@annotate.final
class RoqmeEstimate(IdlStruct, typename="RoqmeDDSTopics::RoqmeEstimate"):
    name: str = ""
    annotate.key("name")
    value: t.float64 = 0.0


@dataclass
@annotate.final
class UnkeyedRoqmeDoubleContext(IdlStruct, typename="RoqmeDDSTopics::RoqmeDoubleContext"):
    name: str = ""
    value: t.sequence[t.float64] = field(default_factory=list)


@dataclass
@annotate.final
class UnkeyedRoqmeEstimate(IdlStruct, typename="RoqmeDDSTopics::RoqmeEstimate"):
    name: str = ""
    value: t.float64 = 0.0


def robot_types(final):
    """The robot's own message types; final (as ROS 2 declares them) or appendable (for XCDR2's DHEADERs)."""
    ext = annotate.final if final else annotate.appendable

    @dataclass
    @ext
    class ChargerInfo(IdlStruct, typename="my_robot_msgs::msg::dds_::ChargerInfo_"):
        dock_id: t.bounded_str[16] = ""
        reachable: bool = True
        last_seen: Time = field(default_factory=Time)

    @dataclass
    @ext
    class PowerStatus(IdlStruct, typename="my_robot_msgs::msg::dds_::PowerStatus_"):
        header: Header = field(default_factory=Header)
        charge_percent: t.float32 = 0.0
        voltage: t.float32 = 48.0
        status: t.uint8 = 0
        charger: ChargerInfo = field(default_factory=ChargerInfo)
        cell_voltages: t.sequence[t.float32] = field(default_factory=list)

    @dataclass
    @ext
    class SpeedLimit(IdlStruct, typename="nav2_msgs::msg::dds_::SpeedLimit_"):
        header: Header = field(default_factory=Header)
        percentage: bool = False
        speed_limit: t.float64 = 0.0

    @dataclass
    @ext
    class Point(IdlStruct, typename="miron_test_msgs::msg::dds_::Point_"):
        tag: t.uint8 = 0
        x: t.float64 = 0.0
        y: t.float64 = 0.0

    @dataclass
    @ext
    class AllKinds(IdlStruct, typename="miron_test_msgs::msg::dds_::AllKinds_"):
        small: t.uint8 = 7
        big: t.float64 = 0.0
        flag: bool = False
        i8: t.int8 = 0
        i16: t.int16 = 0
        u16: t.uint16 = 0
        i32: t.int32 = 0
        u32: t.uint32 = 0
        i64: t.int64 = 0
        u64: t.uint64 = 0
        f32: t.float32 = 0.0
        b: t.uint8 = 0
        c: t.uint8 = 0
        text: str = ""
        short_text: t.bounded_str[8] = "short"
        fixed: t.array[t.float64, 3] = field(default_factory=lambda: [0.0] * 3)
        bounded: t.sequence[t.int32, 4] = field(default_factory=lambda: [1, 2])
        unbounded: t.sequence[t.int16] = field(default_factory=list)
        names: t.sequence[str] = field(default_factory=list)
        fixed_names: t.array[t.bounded_str[5], 2] = field(default_factory=lambda: ["", ""])
        flags: t.sequence[bool] = field(default_factory=list)
        points: t.sequence[Point] = field(default_factory=list)
        fixed_points: t.array[Point, 2] = field(default_factory=lambda: [Point(), Point()])
        some_points: t.sequence[Point, 3] = field(default_factory=list)
        stamp: Time = field(default_factory=Time)
        last: t.uint8 = 0

    return {"my_robot_msgs/PowerStatus": PowerStatus, "my_robot_msgs/ChargerInfo": ChargerInfo,
            "nav2_msgs/SpeedLimit": SpeedLimit, "miron_test_msgs/AllKinds": AllKinds, "miron_test_msgs/Point": Point}


ROBOT_TYPES = robot_types(True)
APPENDABLE_TYPES = robot_types(False)

TYPES = {
    "sensor_msgs/BatteryState": BatteryState, "std_msgs/String": String, "std_msgs/Float64": Float64,
    "std_msgs/Float32": Float32, "std_msgs/Bool": Bool, "std_msgs/Int32": Int32,
    "RoqmeDoubleContext": RoqmeDoubleContext, "RoqmeIntContext": RoqmeIntContext,
    "RoqmeBoolContext": RoqmeBoolContext, "RoqmeEnumContext": RoqmeEnumContext,
    "RoqmeEventContext": RoqmeEventContext, "RoqmeEstimate": RoqmeEstimate,
    "unkeyed RoqmeDoubleContext": UnkeyedRoqmeDoubleContext, "unkeyed RoqmeEstimate": UnkeyedRoqmeEstimate,
}
TYPES.update(ROBOT_TYPES)


@dataclass
@annotate.final
class TruncatedPowerStatus(IdlStruct, typename="my_robot_msgs::msg::dds_::PowerStatus_"):
    """A robot whose PowerStatus is not the bridge's: same name, only the header (its samples end early)."""
    header: Header = field(default_factory=Header)


TYPES["truncated my_robot_msgs/PowerStatus"] = TruncatedPowerStatus

out_lock = threading.Lock()


def emit(**event):
    with out_lock:
        sys.stdout.write(json.dumps(event) + "\n")
        sys.stdout.flush()


def build(cls, data):
    """A message of cls from a dict; nested dataclasses from nested dicts (also in lists), absent fields default."""
    kwargs = {}
    defaults = cls()
    for f in dataclasses.fields(cls):
        if f.name not in data:
            continue
        v = data[f.name]
        d = getattr(defaults, f.name)
        if isinstance(v, dict):
            v = build(type(d), v)
        elif isinstance(v, list) and v and isinstance(v[0], dict):
            v = [build(element_type(cls, f.name), x) for x in v]
        kwargs[f.name] = v
    return cls(**kwargs)


def element_type(cls, name):
    """The dataclass a list field holds, from its annotation (sequence[Point], array[Point, 2])."""
    hint = typing.get_type_hints(cls, include_extras=True)[name]
    for a in typing.get_args(hint):
        inner = getattr(a, "subtype", None)
        if inner is not None and dataclasses.is_dataclass(inner):
            return inner
    raise TypeError("no struct element type for " + name)


def encode(obj):
    if dataclasses.is_dataclass(obj):
        return {f.name: encode(getattr(obj, f.name)) for f in dataclasses.fields(obj)}
    if isinstance(obj, (list, tuple)):
        return [encode(x) for x in obj]
    if isinstance(obj, float) and obj != obj:
        return "NaN"
    return obj


class Peer:
    def __init__(self, domain):
        self.dp = DomainParticipant(domain) if domain >= 0 else None
        self.entities = {}  # id -> ("reader"|"writer", entity, type)
        self.lock = threading.Lock()
        if self.dp is not None:
            threading.Thread(target=self.poll, daemon=True).start()

    def qos(self, cmd):
        policies = [Policy.Reliability.Reliable(duration(seconds=1)) if cmd.get("reliability", "reliable") == "reliable"
                    else Policy.Reliability.BestEffort,
                    Policy.History.KeepLast(int(cmd.get("depth", 10)))]
        policies.append(Policy.Durability.TransientLocal if cmd.get("durability") == "transient_local"
                        else Policy.Durability.Volatile)
        return Qos(*policies)

    def create(self, cmd, kind):
        cls = TYPES[cmd["type"]]
        topic = Topic(self.dp, cmd["topic"], cls)
        pq = Qos(Policy.Partition([cmd["partition"]])) if cmd.get("partition") else None
        if kind == "writer":
            ent = DataWriter(Publisher(self.dp, qos=pq), topic, qos=self.qos(cmd))
        else:
            ent = DataReader(Subscriber(self.dp, qos=pq), topic, qos=self.qos(cmd))
        with self.lock:
            self.entities[cmd["id"]] = (kind, ent, cls)

    def matched(self, ident):
        kind, ent, _ = self.entities[ident]
        return len(ent.get_matched_subscriptions() if kind == "writer" else ent.get_matched_publications())

    def poll(self):
        while True:
            with self.lock:
                readers = [(i, e) for i, (k, e, _) in self.entities.items() if k == "reader"]
            for ident, reader in readers:
                try:
                    for s in reader.take(N=64):
                        if isinstance(s, IdlStruct):  # not an InvalidSample (dispose, no writers)
                            emit(event="sample", id=ident, data=encode(s))
                except Exception as e:  # a closed reader
                    pass
            time.sleep(0.01)

    def handle(self, cmd):
        op = cmd["op"]
        if op in ("writer", "reader"):
            self.create(cmd, op)
        elif op == "write":
            kind, ent, cls = self.entities[cmd["id"]]
            ent.write(build(cls, cmd.get("data", {})))
        elif op == "dispose":  # a keyed instance, as a RoQME tool does with a context it no longer provides
            kind, ent, cls = self.entities[cmd["id"]]
            ent.dispose(build(cls, cmd.get("data", {})))
        elif op == "await_matched":
            want, end = int(cmd.get("count", 1)), time.time() + float(cmd.get("timeout", 30))
            while self.matched(cmd["id"]) < want and time.time() < end:
                time.sleep(0.02)
            n = self.matched(cmd["id"])
            emit(event="matched" if n >= want else "timeout", id=cmd["id"], count=n)
            return
        elif op == "matched":
            emit(event="count", id=cmd["id"], count=self.matched(cmd["id"]))
            return
        elif op == "close":
            with self.lock:
                self.entities.pop(cmd["id"])  # the last reference: Cyclone deletes the entity
        elif op == "encode":
            types = APPENDABLE_TYPES if cmd.get("appendable") else ROBOT_TYPES
            msg = build(types[cmd["type"]], cmd.get("data", {}))
            emit(event="encoded", hex=msg.serialize(use_version_2=bool(cmd.get("xcdr2"))).hex())
            return
        elif op == "decode":
            types = APPENDABLE_TYPES if cmd.get("appendable") else ROBOT_TYPES
            emit(event="decoded", data=encode(types[cmd["type"]].deserialize(bytes.fromhex(cmd["hex"]))))
            return
        elif op == "quit":
            emit(event="ok", op=op)
            sys.stdout.flush()
            raise SystemExit(0)
        else:
            raise ValueError("unknown op " + op)
        emit(event="ok", op=op, id=cmd.get("id"))


def main():
    domain = -1 if "--codec" in sys.argv else int(sys.argv[1]) if len(sys.argv) > 1 else 0
    peer = Peer(domain)
    emit(event="ready")
    for line in sys.stdin:
        line = line.strip()
        if not line:
            continue
        try:
            peer.handle(json.loads(line))
        except SystemExit:
            raise
        except Exception as e:
            emit(event="error", message="%s: %s" % (type(e).__name__, e))


if __name__ == "__main__":
    main()
