// How the viewer's page moves a several-feature scene's parts (framework/view/web/joint.js), with
// the page's own three.js: the moving body's parts follow its offset and its twist about the
// joint's axis, R(twist) (at + deviation) + offset (docs/assemblies.md, JointStage), the fixed
// body's parts stay, and a part's position deviation (and a seated part's seat) is drawn
// exaggerated as the page asks. And a one-feature scene's moving part: a screw's by its turn and
// its advance.
//
// node joint_placement_test.mjs THREE_MODULE_JS   (exit 0 when every check holds)
import assert from 'node:assert/strict';
import { pathToFileURL } from 'node:url';
import * as J from '../../framework/view/web/joint.js';

const THREE = await import(pathToFileURL(process.argv[2]).href);
const near = (got, want, what, tolerance = 1e-9) => {
  for (let k = 0; k < 3; ++k) {
    assert.ok(Math.abs(got[k] - want[k]) <= tolerance,
      `${what}: got (${got.join(', ')}), expected (${want.join(', ')})`);
  }
};
const world = (object, p) => {
  object.updateWorldMatrix(true, false);  // its parents first: the body moves the holder
  return new THREE.Vector3(...p).applyMatrix4(object.matrixWorld).toArray();
};

// The keyed hub: the hub (the bore's and the keyway's outer part) moves, so a state's offset is
// the joint frame's reflected in z. Its keyway's axis lies at (0, 16.3 mm) plus its deviation.
const info = { features: [{ name: 'bore', moving: 'outer' }, { name: 'key', moving: 'outer' }] };
const keyway = { deviation_um: [-0.9, -3.1] };
const state = { depth: 0.012, offsetX: 3e-6, offsetZ: -2e-6, angle: 0.25, force: [1, -20, 4] };

// The pose: the offset drawn `factor` times, its z reflected back; the depth and twist true.
const pose = J.bodyPose(state, info, 100);
near([pose.x, pose.y, pose.z], [0.3, 12, 0.2], 'body pose, mm');
assert.equal(pose.twist, 0.25);
near(J.bodyForce(state, info), [1, -20, -4], 'force in the joint frame');
const innerMoves = { features: [{ name: 'bore', moving: 'inner' }] };
near([J.bodyPose(state, innerMoves, 1).z, 0, 0], [-0.002, 0, 0], 'no reflection, inner moving');

// The moving body's group placed as the page places it, the keyway's mesh in a holder of its
// own that draws its deviation 100 times (the mesh carries it once).
const body = new THREE.Group();
const holder = new THREE.Group();
body.add(holder);
holder.position.set(...J.deviationShift(keyway, 100));
J.placeBody(body, pose);
const axis = [0 - 0.9e-3, -22.5, 16.3 - 3.1e-3];  // the keyway's centre in its mesh, mm
const drawnAxis = [axis[0] + 99 * -0.9e-3, axis[1], axis[2] + 99 * -3.1e-3];
const got = world(holder, axis);
// R(twist) turns (x, z) to (x cos + z sin, -x sin + z cos): the keyway swings about the joint's
// axis (the twist turns it by 16.3 mm * 0.25 across), not about its own.
const c = Math.cos(0.25), s = Math.sin(0.25);
const expected = [c * drawnAxis[0] + s * drawnAxis[2] + 0.3, drawnAxis[1] + 12,
  -s * drawnAxis[0] + c * drawnAxis[2] + 0.2];
near(got, expected, 'keyway under a twist', 1e-6);
near(J.onMovingBody(pose, drawnAxis), expected, 'onMovingBody', 1e-9);
assert.ok(got[0] > 4.0, `a positive twist turns +z towards +x: x = ${got[0]} mm`);
// The bore (on the joint's axis) only moves by the offset.
near(world(body, [0, -22.5, 0]), [0.3, -10.5, 0.2], 'bore under a twist', 1e-9);

// A twist of zero and no offset leaves the body's parts where the server placed them; factor 1
// draws the deviation once.
J.placeBody(body, J.bodyPose({ depth: 0, offsetX: 0, offsetZ: 0, angle: 0 }, info, 1));
holder.position.set(...J.deviationShift(keyway, 1));
near(world(holder, axis), axis, 'zero pose');

// The fixed body's group is never moved: its parts stay whatever the state.
const fixed = new THREE.Group();
near(world(fixed, [0, 25, 16.3]), [0, 25, 16.3], 'fixed part');

// A sequence's seated key (key-then-hub's hub step): its mesh carries its deviation and its seat
// once, both at their true size; the page draws their sum `factor` times, as it drew the seat
// while the key step ran (its moving part's offset).
const seated = { deviation_um: [0.5, -1.0], seat_um: [0.25, 0] };
const key = new THREE.Group();
fixed.add(key);
key.position.set(...J.deviationShift(seated, 100));
const keyAxis = [0 + 0.75e-3, -5, 16.3 - 1.0e-3];  // at + deviation + seat, mm
near(world(key, keyAxis), [keyAxis[0] + 99 * 0.75e-3, -5, keyAxis[2] + 99 * -1.0e-3],
  'seated key', 1e-9);
near(J.deviationShift(seated, 1), [0, 0, 0], 'factor 1 draws the seat once');

// A one-feature screw (a thread scene): the bolt turns by the pose's angle, R(angle), and advances
// by the depth, as its contact analyzer places it. At depth = P angle / 2 pi (screw phase zero) a
// point of its helix, (r cos theta, c theta, -r sin theta) with c = P / 2 pi, lands on the same
// helix at theta + angle: the nut's, whose flanks the bolt's then meet.
const screwScene = { rotational: true, screw: true };
const lead = 1.5, c1 = lead / (2 * Math.PI), r = 4.5, theta = -2.3, turn = 7.9;
const bolt = new THREE.Group();
J.placeBody(bolt, J.scenePose({ depth: c1 * turn / 1000, offsetX: 0, offsetZ: 0, angle: turn },
  screwScene, 100));
near(world(bolt, [r * Math.cos(theta), c1 * theta, -r * Math.sin(theta)]),
  [r * Math.cos(theta + turn), c1 * (theta + turn), -r * Math.sin(theta + turn)], 'screw', 1e-9);
// A pair that mates by rotation alone stays at its centre whatever its depth.
const turned = { depth: 0.002, offsetX: 1e-6, offsetZ: 0, angle: 0.5 };
const ball = J.scenePose(turned, { rotational: true }, 1);
near([ball.y, ball.twist, 0], [0, -0.5, 0], 'knuckle bearing');
const fit = J.scenePose(turned, {}, 10);
near([fit.x, fit.y, 0], [0.01, 2, 0], 'a fit advances by its depth');
console.log('joint placement: every check holds');
