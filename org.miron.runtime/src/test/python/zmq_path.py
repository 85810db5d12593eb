#!/usr/bin/env python3
"""The estimate -> variant path of the MIRoN bus, driven from pyzmq (docs/performance.md, issue 39).

Modes (loopback TCP only):
  floor [--warmup W] [--rounds N]
      the libzmq floor of the path: a relay process (below) stands in for broker and engine, and
      the driver runs against it; what is left is libzmq, loopback TCP and this script.
  drive --in EP --out EP [--warmup W] [--rounds N]
      only the driver, against a broker started elsewhere (the bench's, or `miron run`): EP are
      the broker's bus endpoints (XSUB in, XPUB out).
  relay
      the floor's stand-in: a libzmq XSUB/XPUB proxy (zmq.proxy, C code in a thread, the GIL
      released) on two free ports, and an echo in the engine's place that answers every
      `roqme.estimate` with a `miron.variant.task` body like the engine's; prints its endpoints as
      one JSON line, runs until its standard input closes.

The driver publishes `roqme.estimate` bodies into the broker's XSUB side, power_autonomy 0.2 and
0.9 in turn, so that the intralogistics model's `task` variant alternates dock / pickDeliverCharge
(the engine publishes a variant only when it changes), and subscribes to `miron.variant.` on the
XPUB side; one estimate at a time, timed with time.perf_counter_ns from just before the send to
the variant received. Warm-up rounds first, not counted. It prints one JSON line:
{"mode", "warmup", "rounds", "p50_ms", "p99_ms", "max_ms", "libzmq", "pyzmq"}, or
{"mode", "error"} and exit status 1.
"""

import argparse
import json
import math
import sys
import threading
import time

import zmq

ROUND_TIMEOUT_MS = 5000
# The variant each power_autonomy value leads to on the intralogistics model (noBattery below 0.3).
VALUES = ((0.2, "dock"), (0.9, "pickDeliverCharge"))


def estimate(value):
    return json.dumps({"name": "power_autonomy", "namespace": "Intralogistics", "value": value,
                       "time": int(time.time() * 1000)}).encode()


def percentile(sorted_ns, p):
    """As org.miron.runtime.bench.Stats: the ceil(p% of n)-th smallest, in ms."""
    i = max(0, min(len(sorted_ns) - 1, math.ceil(p / 100.0 * len(sorted_ns)) - 1))
    return sorted_ns[i] / 1e6


class Driver:
    def __init__(self, ctx, bus_in, bus_out):
        self.pub = ctx.socket(zmq.PUB)
        self.pub.connect(bus_in)
        self.sub = ctx.socket(zmq.SUB)
        self.sub.setsockopt(zmq.SUBSCRIBE, b"miron.variant.")
        self.sub.connect(bus_out)
        self.next = 0  # index into VALUES of the next estimate

    def _await(self, expect, timeout_ms):
        """The first miron.variant.task carrying `expect`, or None after timeout_ms; others skipped."""
        needle = ('"%s"' % expect).encode()
        deadline = time.monotonic() + timeout_ms / 1000.0
        while True:
            left = int((deadline - time.monotonic()) * 1000)
            if left <= 0 or not self.sub.poll(left):
                return None
            topic, body = self.sub.recv_multipart()
            if topic == b"miron.variant.task" and needle in body:
                return time.perf_counter_ns()

    def handshake(self):
        """Until one estimate comes back as a variant: the subscriptions have reached every hop
        (ZeroMQ drops what a PUB sends before its peer subscribed). Then the variant's state is
        known, so every later estimate changes it."""
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            value, expect = VALUES[self.next]
            self.pub.send_multipart([b"roqme.estimate", estimate(value)])
            self.next = 1 - self.next
            if self._await(expect, 200) is not None:
                # The broker's cache may re-send an older variant on our subscription: let it pass.
                while self.sub.poll(200):
                    self.sub.recv_multipart()
                return
        raise RuntimeError("no miron.variant.task within 30 s of publishing estimates")

    def round(self):
        value, expect = VALUES[self.next]
        self.next = 1 - self.next
        body = estimate(value)
        t0 = time.perf_counter_ns()
        self.pub.send_multipart([b"roqme.estimate", body])
        t1 = self._await(expect, ROUND_TIMEOUT_MS)
        if t1 is None:
            raise RuntimeError("no miron.variant.task %s within %d ms of power_autonomy = %s"
                               % (expect, ROUND_TIMEOUT_MS, value))
        return t1 - t0


def drive(mode, bus_in, bus_out, warmup, rounds):
    ctx = zmq.Context()
    try:
        d = Driver(ctx, bus_in, bus_out)
        d.handshake()
        for _ in range(warmup):
            d.round()
        times = sorted(d.round() for _ in range(rounds))
        return {"mode": mode, "warmup": warmup, "rounds": rounds, "p50_ms": percentile(times, 50),
                "p99_ms": percentile(times, 99), "max_ms": times[-1] / 1e6,
                "libzmq": zmq.zmq_version(), "pyzmq": zmq.pyzmq_version()}
    finally:
        ctx.destroy(linger=0)


def relay():
    ctx = zmq.Context()
    xsub = ctx.socket(zmq.XSUB)
    xsub.bind("tcp://127.0.0.1:*")
    xpub = ctx.socket(zmq.XPUB)
    xpub.bind("tcp://127.0.0.1:*")
    bus_in = xsub.getsockopt_string(zmq.LAST_ENDPOINT)
    bus_out = xpub.getsockopt_string(zmq.LAST_ENDPOINT)
    # zmq.proxy returns (raising ContextTerminated) when the context is destroyed at exit.
    threading.Thread(target=lambda: _quietly(zmq.proxy, xsub, xpub), daemon=True).start()
    # The echo: the engine's subscription and its answer, with no decision in between.
    sub = ctx.socket(zmq.SUB)
    sub.setsockopt(zmq.SUBSCRIBE, b"roqme.estimate")
    sub.connect(bus_out)
    pub = ctx.socket(zmq.PUB)
    pub.connect(bus_in)
    threading.Thread(target=lambda: _quietly(echo, sub, pub), daemon=True).start()
    print(json.dumps({"in": bus_in, "out": bus_out}), flush=True)
    sys.stdin.read()  # until the parent closes our standard input (or dies)


def echo(sub, pub):
    seq = 0
    while True:
        _, body = sub.recv_multipart()
        value = json.loads(body)["value"]
        seq += 1
        pub.send_multipart([b"miron.variant.task", json.dumps(
            {"varpoint": "task", "value": "dock" if value < 0.3 else "pickDeliverCharge", "seq": seq,
             "time": int(time.time() * 1000)}).encode()])


def _quietly(f, *args):
    try:
        f(*args)
    except zmq.ZMQError:
        pass  # the context went away: the relay is ending


def floor(warmup, rounds):
    import subprocess
    proc = subprocess.Popen([sys.executable, __file__, "relay"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            text=True)
    try:
        line = proc.stdout.readline()
        if not line:
            raise RuntimeError("the relay did not start (exit status %s)" % proc.wait())
        eps = json.loads(line)
        return drive("floor", eps["in"], eps["out"], warmup, rounds)
    finally:
        proc.stdin.close()
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            proc.kill()


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("mode", choices=["floor", "drive", "relay"])
    p.add_argument("--in", dest="bus_in", help="the broker's XSUB endpoint (drive)")
    p.add_argument("--out", dest="bus_out", help="the broker's XPUB endpoint (drive)")
    p.add_argument("--warmup", type=int, default=300)
    p.add_argument("--rounds", type=int, default=1000)
    a = p.parse_args()
    if a.mode == "relay":
        relay()
        return 0
    for ep in (a.bus_in, a.bus_out):
        if ep is not None and not ep.startswith("tcp://127.0.0.1:"):
            p.error("loopback endpoints only (tcp://127.0.0.1:PORT): " + ep)
    if a.mode == "drive" and (a.bus_in is None or a.bus_out is None):
        p.error("drive needs --in and --out")
    try:
        result = floor(a.warmup, a.rounds) if a.mode == "floor" else drive("drive", a.bus_in, a.bus_out, a.warmup,
                                                                            a.rounds)
    except RuntimeError as e:
        print(json.dumps({"mode": a.mode, "error": str(e)}), flush=True)
        return 1
    print(json.dumps(result), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
