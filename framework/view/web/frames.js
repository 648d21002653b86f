// Readers of the viewer's binary WebSocket frames; the layout is described in
// framework/view/README.md ("Frame format") and written by framework/view/frame_codec.cc.
export const KIND_MESH = 1, KIND_STATE = 2, KIND_HISTORY = 3;
export const FLAG_ENGAGED = 1, FLAG_INTERFERENCE = 2, FLAG_GUARD_FAULT = 4,
  FLAG_FINISHED = 8, FLAG_SPACE_KNOWN = 16;

export function frameKind(buffer) {
  const v = new DataView(buffer);
  if (buffer.byteLength < 8 || v.getUint32(0, true) !== 0x57564646) return 0;  // "FFVW"
  if (v.getUint16(4, true) !== 1) return 0;
  return v.getUint16(6, true);
}

export function readMesh(buffer) {
  const v = new DataView(buffer);
  const part = v.getUint8(8), placeholder = v.getUint8(9) !== 0, feature = v.getUint16(10, true);
  const cells = v.getUint32(12, true);
  let at = 16;
  const floats = (count) => {
    const out = new Float32Array(count);
    for (let i = 0; i < count; ++i, at += 4) out[i] = v.getFloat32(at, true);
    return out;
  };
  const corners = floats(cells * 12), directions = floats(cells * 3), variation = floats(cells);
  return { part, feature, placeholder, cells, corners, directions, variation };
}

export function readState(buffer) {
  const v = new DataView(buffer);
  const f = (at) => v.getFloat32(at, true);
  const s = {
    time: v.getFloat64(8, true), tick: v.getUint32(16, true), dropped: v.getUint32(20, true),
    depth: f(24), offsetX: f(28), offsetZ: f(32), angle: f(36),
    force: [f(40), f(44), f(48)], torque: [f(52), f(56), f(60)],
    offsetDistance: f(64), offsetAngle: f(68), assemblyExtent: f(72), penetration: f(76),
    maxInterference: f(80), stage: v.getUint8(84), flags: v.getUint8(85),
    pressureMax: f(88),
  };
  const vertices = v.getUint16(86, true), cells = v.getUint32(92, true);
  s.space = [];
  let at = 96;
  for (let k = 0; k < vertices; ++k, at += 8) s.space.push([f(at), f(at + 4)]);
  s.pressure = new Uint8Array(buffer, at, cells);
  return s;
}

export function readHistory(buffer) {
  const v = new DataView(buffer);
  const rows = v.getUint32(8, true);
  const out = [];
  let at = 12;
  for (let r = 0; r < rows; ++r) {
    const x = [];
    for (let k = 0; k < 12; ++k, at += 4) x.push(v.getFloat32(at, true));
    out.push({ time: x[0], depth: x[1], offsetX: x[2], offsetZ: x[3], angle: x[4],
      force: [x[5], x[6], x[7]], torque: [x[8], x[9], x[10]], stage: x[11] });
  }
  return out;
}
