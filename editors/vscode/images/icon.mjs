#!/usr/bin/env node
// Draws images/icon.png (128x128, the Marketplace's size): a behaviour tree on a dark square, the
// variation point (MIRoN's adaptation) in orange. Plain Node (zlib), no image library:
//   node images/icon.mjs
import { writeFileSync } from 'node:fs';
import { deflateSync } from 'node:zlib';

const size = 128;
const px = new Float64Array(size * size * 4); // RGBA, 0..1

function blend(x, y, [r, g, b], a) {
    if (x < 0 || y < 0 || x >= size || y >= size || a <= 0) return;
    const i = (y * size + x) * 4;
    const da = px[i + 3];
    const oa = a + da * (1 - a);
    for (const [k, c] of [[0, r], [1, g], [2, b]]) px[i + k] = (c * a + px[i + k] * da * (1 - a)) / (oa || 1);
    px[i + 3] = oa;
}
/** Fills the pixels where `inside(x, y)` (a signed distance, negative inside), anti-aliased. */
function fill(dist, colour) {
    for (let y = 0; y < size; y++) {
        for (let x = 0; x < size; x++) {
            const d = dist(x + 0.5, y + 0.5);
            blend(x, y, colour, Math.max(0, Math.min(1, 0.5 - d)));
        }
    }
}
const roundedSquare = (r) => (x, y) => {
    const qx = Math.abs(x - 64) - (64 - r), qy = Math.abs(y - 64) - (64 - r);
    return Math.hypot(Math.max(qx, 0), Math.max(qy, 0)) + Math.min(Math.max(qx, qy), 0) - r;
};
const circle = (cx, cy, r) => (x, y) => Math.hypot(x - cx, y - cy) - r;
const segment = (ax, ay, bx, by, w) => (x, y) => {
    const t = Math.max(0, Math.min(1, ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / ((bx - ax) ** 2 + (by - ay) ** 2)));
    return Math.hypot(x - ax - t * (bx - ax), y - ay - t * (by - ay)) - w / 2;
};

const navy = [0.09, 0.16, 0.3], white = [0.93, 0.95, 0.98], orange = [1, 0.6, 0.15];
fill(roundedSquare(22), navy);
const root = [64, 30], left = [34, 70], right = [94, 70], leaves = [[20, 102], [48, 102], [80, 102], [108, 102]];
for (const [a, b] of [[root, left], [root, right], [left, leaves[0]], [left, leaves[1]], [right, leaves[2]], [right, leaves[3]]]) {
    fill(segment(a[0], a[1], b[0], b[1], 5), white);
}
fill(circle(...root, 12), white);
fill(circle(...left, 10), white);
fill(circle(...right, 11), orange);
for (const l of leaves) fill(circle(...l, 7), white);

// PNG: RGBA, 8 bits, filter 0 on every row.
const raw = Buffer.alloc(size * (size * 4 + 1));
for (let y = 0; y < size; y++) {
    raw[y * (size * 4 + 1)] = 0;
    for (let x = 0; x < size * 4; x++) raw[y * (size * 4 + 1) + 1 + x] = Math.round(px[y * size * 4 + x] * 255);
}
const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
});
const crc = (buf) => { let c = 0xffffffff; for (const b of buf) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8); return (c ^ 0xffffffff) >>> 0; };
const chunk = (type, data) => {
    const head = Buffer.alloc(8); head.writeUInt32BE(data.length, 0); head.write(type, 4, 'ascii');
    const tail = Buffer.alloc(4); tail.writeUInt32BE(crc(Buffer.concat([head.subarray(4), data])), 0);
    return Buffer.concat([head, data, tail]);
};
const ihdr = Buffer.alloc(13);
ihdr.writeUInt32BE(size, 0); ihdr.writeUInt32BE(size, 4); ihdr[8] = 8; ihdr[9] = 6;
writeFileSync(new URL('./icon.png', import.meta.url), Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', ihdr), chunk('IDAT', deflateSync(raw, { level: 9 })), chunk('IEND', Buffer.alloc(0))]));
