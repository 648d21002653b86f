// Placement of a several-feature scene's parts on the page. The server sends every part's mesh
// already in the joint frame (framework/view/part_placement.h): the fixed body's where they stay,
// the moving body's where they lie at the body's zero pose. Each tick the page moves the moving
// body's parts together by the body's pose; these functions say how. Pure (no three.js, no DOM),
// so that tests/browser/joint_placement_test.mjs checks them under Node.
export const MM = 1000;  // frames are in m; the scene is drawn in mm

// The moving body's pose in the joint frame, from a state frame or a history row: its offset
// across the axis drawn `factor` times its size, its depth and its twist true (mm, rad). The
// state's offset is in the datum feature's outer part's frame, the joint frame reflected in z
// where that part is on the moving body (ViewSample, AnalyzerPose): the reflection is undone.
export function bodyPose(state, info, factor) {
  const reflect = info.features[0].moving === 'outer';
  return {
    x: MM * factor * state.offsetX,
    y: MM * state.depth,
    z: MM * factor * (reflect ? -state.offsetZ : state.offsetZ),
    twist: state.angle,
  };
}

// The force on the moving body in the joint frame (N), from the state's (reflected as its offset).
export function bodyForce(state, info) {
  const [fx, fy, fz] = state.force;
  return [fx, fy, info.features[0].moving === 'outer' ? -fz : fz];
}

// A point of the moving body (mm, joint frame at the body's zero pose) where the body stands:
// turned by the twist about the joint's axis, R(twist) (x, z) = (x cos + z sin, -x sin + z cos)
// (docs/assemblies.md), then moved by the pose. placeBody gives a three.js group the same
// transform.
export function onMovingBody(pose, p) {
  const c = Math.cos(pose.twist), s = Math.sin(pose.twist);
  return [c * p[0] + s * p[2] + pose.x, p[1] + pose.y, -s * p[0] + c * p[2] + pose.z];
}

// A one-feature scene's moving part (the inner one: the page draws the outer part fixed) on the
// page, from a state frame: its offset across the axis drawn `factor` times its size, its depth
// true except for a pair that mates by rotation alone (the knuckle bearing, drawn at its centre).
// A screw (the scene message's `screw`, a thread) advances along the axis as it turns and is
// turned by the pose's angle as its contact analyzer turns the bolt, R(angle); the other pairs
// by R(-angle).
export function scenePose(state, scene, factor) {
  const screw = Boolean(scene && scene.screw);
  const rotational = Boolean(scene && scene.rotational);
  return {
    x: MM * factor * state.offsetX,
    y: rotational && !screw ? 0 : MM * state.depth,
    z: MM * factor * state.offsetZ,
    twist: screw ? state.angle : -state.angle,
  };
}

// Puts a three.js object (the moving body's group) at the pose: three.js turns by rotation.y
// before it translates, and its rotation about y by a is R(a).
export function placeBody(object, pose) {
  object.position.set(pose.x, pose.y, pose.z);
  object.rotation.set(0, pose.twist, 0);
}

// How far (mm) the page moves a part's mesh within its body so that the part's position
// deviation (`deviation_um` of the scene message; the mesh carries it at its true size) is drawn
// `factor` times its size, as the skin model deviations are; and so is a seated part's seat
// (`seat_um`: where a sequence's earlier step left it, that step's offset across its axis, which
// the page drew exaggerated while that step ran).
export function deviationShift(part, factor) {
  const [x, z] = part.deviation_um;
  const [sx, sz] = part.seat_um || [0, 0];
  return [(factor - 1) * (x + sx) * 1e-3, 0, (factor - 1) * (z + sz) * 1e-3];
}
