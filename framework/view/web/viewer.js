// fitfeel view: draws the parts, the contact pressure, the resistances, the assembly space and
// the force trace from the frames the server streams over /ws (frames.js reads them). A
// several-feature scene draws every feature's parts in the joint frame (joint.js), names the
// features in the panel and over the 3D view, and moves the moving body's parts together. A
// sequence's steps come one scene after another: each scene message replaces the drawn scene, and
// the sequence message says which step is shown and what each finished step left.
import * as THREE from '/three/build/three.module.js';
import { OrbitControls } from '/three/examples/jsm/controls/OrbitControls.js';
import * as F from '/frames.js';
import * as J from '/joint.js';
import * as Live from '/live.js';

const $ = (id) => document.getElementById(id);
const MM = 1000;  // frames are in m; the scene is drawn in mm

// Perceptually uniform palette (viridis anchors), t in [0, 1].
const VIRIDIS = [[68, 1, 84], [72, 40, 120], [62, 74, 137], [49, 104, 142], [38, 130, 142],
  [31, 158, 137], [53, 183, 121], [110, 206, 88], [181, 222, 43], [253, 231, 37]];
function viridis(t) {
  const x = Math.min(Math.max(t, 0), 1) * (VIRIDIS.length - 1);
  const i = Math.min(Math.floor(x), VIRIDIS.length - 2), u = x - i;
  return VIRIDIS[i].map((a, k) => (a + u * (VIRIDIS[i + 1][k] - a)) / 255);
}

// Meshes and geometries are indexed 2 feature + part (part 0 inner, 1 outer): a one-feature
// scene's are 0 and 1.
const view = {
  scene: null, meshes: [null, null], geometry: [null, null], factor: 100, state: null,
  trace: [], history: null, frames: 0, finished: false,
  holders: [],  // several-feature scene: the group holding each part's mesh within its body
  labels: [],   // several-feature scene: each feature's name over its fixed part
  sequence: null,  // a sequence's newest sequence message
  // The largest resistance of the run so far (of a finished run: of its history), N: of the
  // constrained stage, which the trace draws, and of any stage.
  forcePeak: 0, forcePeakAny: 0,
  // A live view's scenes before this one (a comparison's other scene, the scene before an edit):
  // their traces' last rows by label, drawn dashed under this scene's.
  others: new Map(),
  scenes: 0,  // scene messages received
};
// A several-feature scene (the scene message lists its features).
const joint = () => Boolean(view.scene && view.scene.features && view.scene.features.length);
// Each feature's colour: the datum feature's outer part keeps the one-feature page's blue-grey;
// the others take Okabe and Ito's colour-blind-safe set, away from the pressure map's viridis.
const FEATURE_COLOURS = [0x8a9bb0, 0xd55e00, 0xcc79a7, 0xe69f00, 0x0072b2, 0x009e73, 0x56b4e9,
  0x882255];
const featureColour = (i) => FEATURE_COLOURS[i % FEATURE_COLOURS.length];
const cssColour = (c) => `#${c.toString(16).padStart(6, '0')}`;

// --- three.js scene -------------------------------------------------------------------------
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
renderer.setClearColor(0xf4f4f2);
$('scene').appendChild(renderer.domElement);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 10000);
camera.up.set(0, 0, 1);  // the scene's z is up (gravity along -z); the mating axis y lies across
const controls = new OrbitControls(camera, renderer.domElement);
// Drawn on demand (a new frame, a control moved): a software renderer is not kept busy by an
// unchanging picture.
let renderPending = false;
function requestRender() {
  if (renderPending) return;
  renderPending = true;
  requestAnimationFrame(() => {
    renderPending = false;
    renderer.render(scene, camera);
    if (view.labels.length) placeLabels();
    drawKeys();
  });
}
controls.addEventListener('change', requestRender);
scene.add(new THREE.HemisphereLight(0xffffff, 0x888880, 0.85));
const sun = new THREE.DirectionalLight(0xffffff, 0.55);
sun.position.set(1, 2, 3);
scene.add(sun);
// One feature: the inner part, placed at the pose, and the outer part. Several: the moving body's
// parts, placed at the body's pose, and the fixed body's.
const moving = new THREE.Group();
const fixed = new THREE.Group();
scene.add(moving, fixed);
const axialArrow = new THREE.ArrowHelper(new THREE.Vector3(0, -1, 0), new THREE.Vector3(), 1,
  0xc0392b);
const radialArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1,
  0x1f5fbf);
// The resistances act at the leading end, inside the other part: drawn over the surfaces.
for (const arrow of [axialArrow, radialArrow]) {
  for (const part of [arrow.line, arrow.cone]) {
    part.material.depthTest = false;
    part.renderOrder = 10;
  }
}
scene.add(axialArrow, radialArrow);

function resize() {
  const el = $('scene');
  renderer.setSize(el.clientWidth, el.clientHeight);
  camera.aspect = el.clientWidth / Math.max(el.clientHeight, 1);
  camera.updateProjectionMatrix();
  requestRender();
}
window.addEventListener('resize', resize);
resize();

// One quad per cell, corners displaced along the cell's direction by factor * V.
function buildGeometry(mesh) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(mesh.cells * 12), 3));
  const colors = new Float32Array(mesh.cells * 12).fill(0.75);
  g.setAttribute('color', new THREE.BufferAttribute(colors, 3));
  const index = new Uint32Array(mesh.cells * 6);
  for (let c = 0; c < mesh.cells; ++c) {
    index.set([4 * c, 4 * c + 1, 4 * c + 2, 4 * c, 4 * c + 2, 4 * c + 3], 6 * c);
  }
  g.setIndex(new THREE.BufferAttribute(index, 1));
  return g;
}

function displace(part) {
  displaceMesh(view.meshes[part], view.geometry[part]);
}

function displaceMesh(mesh, g) {
  if (!mesh || !g) return;
  const p = g.attributes.position.array, s = view.factor;
  for (let c = 0; c < mesh.cells; ++c) {
    const dv = s * mesh.variation[c];
    for (let k = 0; k < 4; ++k) {
      for (let a = 0; a < 3; ++a) {
        p[12 * c + 3 * k + a] = MM * (mesh.corners[12 * c + 3 * k + a] + dv * mesh.directions[3 * c + a]);
      }
    }
  }
  g.attributes.position.needsUpdate = true;
  g.computeVertexNormals();
  g.computeBoundingSphere();
}

// A comparison's other scene (its scene message marked `companion`, then its meshes), drawn
// below the one the device renders: translucent, its moving part at the rendered part's depth,
// without pressure (it does not run). A several-feature scene's companion is named, not drawn.
const companion = { group: new THREE.Group(), moving: new THREE.Group(), fixed: new THREE.Group(),
  scene: null, pending: 0, drawn: false, meshes: [], geometry: [] };
companion.group.add(companion.moving, companion.fixed);
scene.add(companion.group);

// Frees what a group draws and empties it (three.js r111 has no clear()).
function emptyGroup(group) {
  group.traverse((o) => {
    if (o.geometry) o.geometry.dispose();
    if (o.material) o.material.dispose();
  });
  group.children.slice().forEach((c) => group.remove(c));
}

function clearCompanion() {
  emptyGroup(companion.moving);
  emptyGroup(companion.fixed);
  Object.assign(companion, { scene: null, pending: 0, drawn: false, meshes: [], geometry: [] });
  document.body.dataset.companionParts = 0;
  $('companion-label').hidden = true;
}

function onCompanion(info) {
  clearCompanion();
  companion.scene = info;
  const several = Boolean(info.features && info.features.length);
  companion.pending = several ? 2 * info.features.length : 2;
  companion.drawn = !several;
  $('companion-label').hidden = false;
  $('companion-label').textContent = `${several ? 'Not drawn' : 'Below'}, not rendering: ` +
    `${info.scenario} (${info.inner.name} in ${info.outer.name})`;
}

function addCompanionPart(mesh) {
  companion.pending -= 1;
  if (!companion.drawn || mesh.placeholder) return;
  const g = buildGeometry(mesh);
  companion.meshes[mesh.part] = mesh;
  companion.geometry[mesh.part] = g;
  displaceMesh(mesh, g);
  const material = new THREE.MeshLambertMaterial({ color: mesh.part === 0 ? 0xc8b870 : 0x9aa5b5,
    side: THREE.DoubleSide, transparent: true, opacity: mesh.part === 0 ? 0.55 : 0.25,
    depthWrite: false });
  (mesh.part === 0 ? companion.moving : companion.fixed).add(new THREE.Mesh(g, material));
  document.body.dataset.companionParts = companion.geometry.filter((x) => x).length;
  if (companion.pending === 0) {
    // One and a half of the rendered outer part's heights below it.
    const box = new THREE.Box3().expandByObject(fixed);
    companion.group.position.set(0, 0, box.isEmpty() ? 0 : -1.5 * (box.max.z - box.min.z));
    frameCamera();
  }
  requestRender();
}

// A part made of a CAD feature: the part's own tessellated shape from the scene message, in the
// same mating frame as its render mesh, so the group that moves the primitive moves it too.
function cadGeometry(side) {
  if (!side || !side.cad_mesh) return null;
  const um = side.cad_mesh.positions_um, p = new Float32Array(um.length);
  for (let i = 0; i < um.length; ++i) p[i] = um[i] * 1e-3;
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(p, 3));
  g.computeVertexNormals();
  g.computeBoundingSphere();
  return g;
}

function addPart(mesh) {
  if (joint()) {
    addFeaturePart(mesh);
    return;
  }
  const group = mesh.part === 0 ? moving : fixed;
  group.clear ? group.clear() : group.children.slice().forEach((c) => group.remove(c));
  view.meshes[mesh.part] = mesh;
  if (mesh.placeholder) {
    // No render mesh: a labelled box stands in, so the page is never blank.
    const size = 10, box = new THREE.BoxGeometry(size, size, size);
    const material = new THREE.MeshLambertMaterial({ color: mesh.part === 0 ? 0xd9b100 : 0x999999,
      transparent: true, opacity: mesh.part === 0 ? 0.9 : 0.3 });
    const m = new THREE.Mesh(box, material);
    m.position.y = mesh.part === 0 ? -size / 2 : size / 2;
    group.add(m, new THREE.LineSegments(new THREE.EdgesGeometry(box),
      new THREE.LineBasicMaterial({ color: 0x333333 })));
    group.children[1].position.copy(m.position);
    view.geometry[mesh.part] = null;
    document.body.dataset.parts = view.meshes.filter((m) => m).length;
    if (view.meshes[0] && view.meshes[1]) frameCamera();
    requestRender();
    return;
  }
  const g = buildGeometry(mesh);
  view.geometry[mesh.part] = g;
  document.body.dataset.parts = view.meshes.filter((m) => m).length;
  displace(mesh.part);
  const cad = cadGeometry(mesh.part === 0 ? view.scene.inner : view.scene.outer);
  const material = mesh.part === 0
    ? new THREE.MeshLambertMaterial(cad ? { color: 0xd9b100, side: THREE.DoubleSide }
      : { vertexColors: THREE.VertexColors, side: THREE.DoubleSide })
    : new THREE.MeshLambertMaterial({ color: 0x8a9bb0, side: THREE.DoubleSide, transparent: true,
      opacity: 0.35, depthWrite: false });
  group.add(new THREE.Mesh(cad || g, material));
  if (cad) document.body.dataset.cadParts = (Number(document.body.dataset.cadParts) || 0) + 1;
  if (view.meshes[0] && view.meshes[1]) frameCamera();
  requestRender();
}

// A several-feature scene's part: its mesh comes placed in the joint frame (on the moving body: at
// the body's zero pose), held by a group of its own that draws its position deviation
// exaggerated. Inner parts are opaque, outer parts translucent, each feature in its colour; the
// datum feature's inner part carries the pressure map.
function addFeaturePart(mesh) {
  const feature = view.scene.features[mesh.feature];
  if (!feature) return;
  const k = 2 * mesh.feature + mesh.part;
  const side = mesh.part === 0 ? feature.inner : feature.outer;
  if (view.holders[k] && view.holders[k].parent) view.holders[k].parent.remove(view.holders[k]);
  const holder = new THREE.Group();
  view.holders[k] = holder;
  view.meshes[k] = mesh;
  (side.body === 'moving' ? moving : fixed).add(holder);
  const colour = featureColour(mesh.feature);
  if (mesh.placeholder) {
    // No render mesh: a box at the feature's place stands in.
    const size = 4, box = new THREE.BoxGeometry(size, size, size);
    const m = new THREE.Mesh(box, new THREE.MeshLambertMaterial({ color: colour, transparent: true,
      opacity: mesh.part === 0 ? 0.9 : 0.3 }));
    m.position.set(feature.at_mm[0], mesh.part === 0 ? size / 2 : -size / 2, feature.at_mm[1]);
    holder.add(m);
    view.geometry[k] = null;
  } else {
    const g = buildGeometry(mesh);
    view.geometry[k] = g;
    displace(k);
    const material = k === 0
      ? new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors, side: THREE.DoubleSide })
      : mesh.part === 0
        ? new THREE.MeshLambertMaterial({ color: colour, side: THREE.DoubleSide })
        : new THREE.MeshLambertMaterial({ color: colour, side: THREE.DoubleSide, transparent: true,
          opacity: 0.35, depthWrite: false });
    holder.add(new THREE.Mesh(g, material));
  }
  shiftDeviation(k);
  document.body.dataset.parts = view.holders.filter((h) => h).length;
  if (view.scene.features.every((f, i) => view.meshes[2 * i] && view.meshes[2 * i + 1])) {
    frameCamera();
    makeLabels();
  }
  requestRender();
}

// The part's position deviation drawn `factor` times its size (its mesh carries it once).
function shiftDeviation(k) {
  const holder = view.holders[k], feature = view.scene.features[k >> 1];
  if (!holder || !feature) return;
  holder.position.set(...J.deviationShift((k & 1) ? feature.outer : feature.inner, view.factor));
}

// Each feature's name over its fixed part's far end (the end away from the moving body), kept
// apart on the screen where two would overlap.
function makeLabels() {
  for (const label of view.labels) label.element.remove();
  clearCompanion();
  view.labels = [];
  fixed.updateMatrixWorld(true);
  view.scene.features.forEach((feature, i) => {
    const k = 2 * i + (feature.inner.body === 'fixed' ? 0 : 1);
    const box = new THREE.Box3().expandByObject(view.holders[k]);
    if (box.isEmpty()) return;
    const element = document.createElement('div');
    element.className = 'feature-label';
    element.textContent = feature.name;
    element.style.borderLeftColor = cssColour(featureColour(i));
    $('scene').appendChild(element);
    const centre = box.getCenter(new THREE.Vector3());
    view.labels.push({ element, anchor: new THREE.Vector3(centre.x, box.max.y, box.max.z) });
  });
  requestRender();
}

function placeLabels() {
  const el = $('scene'), w = el.clientWidth, h = el.clientHeight, taken = [];
  for (const label of view.labels) {
    const p = label.anchor.clone().project(camera);
    const visible = p.z < 1 && Math.abs(p.x) <= 1 && Math.abs(p.y) <= 1;
    label.element.hidden = !visible;
    if (!visible) continue;
    const x = (p.x + 1) / 2 * w;
    let y = (1 - p.y) / 2 * h;
    const width = label.element.offsetWidth, height = label.element.offsetHeight;
    // A label stands on its anchor (its bottom edge's centre, viewer.css); one that would cover an
    // earlier one moves up past it.
    for (let moved = true; moved;) {
      moved = false;
      for (const t of taken) {
        if (Math.abs(x - t.x) < (width + t.width) / 2 && y > t.y - t.height && y - height < t.y) {
          y = t.y - t.height;
          moved = true;
        }
      }
    }
    taken.push({ x, y, width, height });
    label.element.style.left = `${x}px`;
    label.element.style.top = `${y}px`;
  }
}

// Both parts as they stand before insertion (the moving one's leading end at the entrance), seen
// from the side, a little from above and in front, so that the mating axis y runs across the
// screen; as close as lets their bounding box fit with a margin for the keys in the corners.
function frameCamera() {
  const saved = moving.position.clone();
  const twist = moving.rotation.y;
  moving.position.set(0, 0, 0);
  if (joint()) moving.rotation.set(0, 0, 0);
  moving.updateMatrixWorld(true);
  const box = new THREE.Box3();
  for (const group of [moving, fixed, companion.group]) box.expandByObject(group);
  moving.position.copy(saved);
  if (joint()) moving.rotation.set(0, twist, 0);
  moving.updateMatrixWorld(true);
  if (box.isEmpty()) return;
  const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
  const r = Math.max(size.x, size.y, size.z);
  camera.position.copy(centre).add(new THREE.Vector3(1, -0.22, 0.42).normalize());
  camera.lookAt(centre);
  camera.updateMatrixWorld(true);
  const e = camera.matrixWorld.elements;
  const right = new THREE.Vector3(e[0], e[1], e[2]), up = new THREE.Vector3(e[4], e[5], e[6]);
  const back = new THREE.Vector3(e[8], e[9], e[10]);
  // A corner at (u, v) across the view and w towards the camera fits at distance d where
  // |u| <= (d - w) tan(half width) and |v| <= (d - w) tan(half height); the box takes 62 % of
  // the width and 70 % of the height, leaving the corners to the keys.
  const tanV = Math.tan(camera.fov * Math.PI / 360), tanH = tanV * camera.aspect;
  let d = 0;
  for (let i = 0; i < 8; ++i) {
    const q = new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
      i & 4 ? box.max.z : box.min.z).sub(centre);
    const w = q.dot(back);
    d = Math.max(d, w + Math.abs(q.dot(right)) / (0.62 * tanH), w + Math.abs(q.dot(up)) / (0.7 * tanV));
  }
  camera.position.copy(centre).addScaledVector(back, d);
  camera.near = Math.max(d - 2 * r, d / 1000);
  camera.far = d + 100 * r;
  camera.updateProjectionMatrix();
  controls.target.copy(centre);
  controls.update();
  view.size = r;
  requestRender();
}

// --- state ---------------------------------------------------------------------------------
function colourPressure(state) {
  const g = view.geometry[0];
  if (!g) return;
  const c = g.attributes.color.array, cells = view.meshes[0].cells;
  const has = state.pressure.length === cells && state.pressureMax > 0;
  for (let k = 0; k < cells; ++k) {
    const q = has ? state.pressure[k] : 0;
    const rgb = q > 0 ? viridis(q / 255) : [0.78, 0.78, 0.76];
    for (let v = 0; v < 4; ++v) c.set(rgb, 12 * k + 3 * v);
  }
  g.attributes.color.needsUpdate = true;
}

// 1, 2 or 5 times a power of ten: the nearest to x on a log scale, or the smallest at least x.
function nice(x) {
  const e = Math.floor(Math.log10(x)), m = x / 10 ** e;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * 10 ** e;
}
function niceUp(x) {
  const e = Math.floor(Math.log10(x)), m = x / 10 ** e;
  return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * 10 ** e;
}

// Arrows are proportional to the force, so that two arrows compare as their forces do: the run's
// largest resistance so far in the constrained stage (in any stage before that stage) is drawn at
// most 30 % of the parts' size, at a round number of newtons per mm of the scene (the key says
// which). A positioning stage may push far harder than the fit resists (the pin's 8.8 kN against
// its 1 kN): its arrows are cut at 60 % of the parts' size and the key says so. Null before any
// force.
function newtonsPerMm() {
  const peak = view.forcePeak || view.forcePeakAny;
  return peak > 0 ? niceUp(peak / (0.3 * (view.size || 20))) : null;
}
function arrowLength(force) {
  const scale = newtonsPerMm();
  return scale ? Math.abs(force) / scale : 0;
}
const arrowLimit = () => 0.6 * (view.size || 20);
const peakOf = (force) => Math.max(Math.abs(force[1]), Math.hypot(force[0], force[2]));
function notePeak(stage, force) {
  view.forcePeakAny = Math.max(view.forcePeakAny, peakOf(force));
  if (stage === 1) view.forcePeak = Math.max(view.forcePeak, peakOf(force));
}

function place(state) {
  if (joint()) {
    // The moving body at its pose in the joint frame; the resistances on it at its datum part's
    // mating end.
    J.placeBody(moving, J.bodyPose(state, view.scene, view.factor));
    drawArrows(moving.position.clone(), J.bodyForce(state, view.scene));
    return;
  }
  J.placeBody(moving, J.scenePose(state, view.scene, view.factor));
  companion.moving.position.set(0, moving.position.y, 0);
  drawArrows(moving.position.clone(), state.force);
}

function drawArrows(tip, force) {
  const [fx, fy, fz] = force, radial = Math.hypot(fx, fz);
  axialArrow.position.copy(tip);
  axialArrow.setDirection(new THREE.Vector3(0, fy >= 0 ? 1 : -1, 0));
  // The head stays a fixed share of the parts' size, never longer than the arrow.
  const head = (l) => Math.min(0.4 * l, 0.04 * (view.size || 20));
  const la = Math.min(arrowLength(fy), arrowLimit());
  axialArrow.visible = la > 1e-6;
  if (axialArrow.visible) axialArrow.setLength(la, head(la), 0.5 * head(la));
  radialArrow.position.copy(tip);
  const lr = Math.min(arrowLength(radial), arrowLimit());
  radialArrow.visible = lr > 1e-6;
  if (radialArrow.visible) {
    radialArrow.setDirection(new THREE.Vector3(fx / radial, 0, fz / radial));
    radialArrow.setLength(lr, head(lr), 0.5 * head(lr));
  }
}

// Three significant digits; thousands in full (1250, not 1.25e+3, which toPrecision gives).
const fmt = (x, d = 3) => (Math.abs(x) >= 1e4 || (Math.abs(x) < 1e-3 && x !== 0))
  ? x.toExponential(2) : Math.abs(x) >= 1e3 ? x.toFixed(0) : x.toPrecision(d);

function showState(state) {
  view.state = state;
  notePeak(state.stage, state.force);
  colourPressure(state);
  place(state);
  const [fx, fy, fz] = state.force;
  const stage = state.stage === 1 ? 'constrained' : 'positioning';
  const finished = (state.flags & F.FLAG_FINISHED) !== 0;
  $('status').textContent = `${finished ? 'finished run' : 'live'} · t ${state.time.toFixed(3)} s · ` +
    `depth ${(MM * state.depth).toFixed(3)} mm · ${stage}` +
    ((state.flags & F.FLAG_INTERFERENCE) ? ' · interference' : '') +
    (state.dropped ? ` · ${state.dropped} samples skipped (the run outpaced the display)` : '');
  // The axial and radial resistances are in the key over the 3D view, by their arrows.
  $('forces').textContent = [
    view.scene && view.scene.rotational ? `torque ${fmt(Math.hypot(...state.torque))} N·m` : '',
    joint() ? `twist ${fmt(1e3 * state.angle)} mrad · torque about the axis ` +
      `${fmt(state.torque[1])} N·m` : ''].filter((t) => t).join(' · ');
  drawLegend(state);
  drawSpace(state);
  if (state.stage === 1) {
    view.axialPeak = Math.max(view.axialPeak || 0, Math.abs(fy));
    document.body.dataset.axialPeak = view.axialPeak;
  }
  document.body.dataset.axial = Math.abs(fy);
  if (!finished && state.stage === 1) {
    view.trace.push([abscissa(state), Math.abs(fy), Math.hypot(fx, fz)]);
    if (view.trace.length > 600) view.trace.shift();  // scrolls: the newest 10 s at 60 Hz
  }
  drawTrace();
  requestRender();
}

// The colour bar of the pressure map with its scale in MPa; grey, and said in words, where
// nothing touches (the map's untouched cells are that grey) or the law gives no pressure map.
const UNTOUCHED = [0.78, 0.78, 0.76];
function drawLegend(state) {
  const cv = $('legend'), g = cv.getContext('2d');
  const none = view.scene && !view.scene.pressure ? 'no pressure map for this law'
    : state.pressureMax > 0 ? '' : 'no contact';
  for (let x = 0; x < cv.width; ++x) {
    const [r, gg, b] = none ? UNTOUCHED : viridis(x / (cv.width - 1));
    g.fillStyle = `rgb(${255 * r},${255 * gg},${255 * b})`;
    g.fillRect(x, 0, 1, cv.height);
  }
  const max = state.pressureMax / 1e6;
  const ticks = $('pressure-ticks');
  ticks.replaceChildren();
  if (!none) {
    [0, 0.5, 1].forEach((t) => {
      const tick = document.createElement('span');
      tick.style.left = `${100 * t}%`;
      tick.textContent = t === 0 ? '0' : t === 1 ? `${fmt(max)} MPa` : fmt(t * max);
      ticks.appendChild(tick);
    });
  }
  ticks.hidden = Boolean(none);
  const range = $('pressure-range');
  range.className = none ? 'none' : '';
  range.textContent = none || `0 to ${fmt(max)} MPa; grey: no contact`;
}

// --- keys over the 3D view -------------------------------------------------------------------
// Screen pixels per mm of the scene at the orbit's centre, where the parts are (a perspective
// view draws nearer things larger: the scale bar and the arrows' key hold at that depth).
function pixelsPerMm() {
  const d = camera.position.distanceTo(controls.target);
  return $('scene').clientHeight / (2 * d * Math.tan(camera.fov * Math.PI / 360));
}

// A round number as it reads: 5, 0.2, 2000 (not 5.00).
const round = (x) => String(+x.toPrecision(3));
const lengthText = (mm) => (mm >= 1 ? `${round(mm)} mm` : `${round(1e3 * mm)} µm`);

// Drawn after every render: a zoom or turn of the camera changes the scale and the axes.
function drawKeys() {
  const ppm = pixelsPerMm();
  if (!(ppm > 0) || !Number.isFinite(ppm)) return;
  const bar = nice(100 / ppm);
  $('scale-line').style.width = `${Math.round(bar * ppm)}px`;
  $('scale-text').textContent = lengthText(bar);
  document.body.dataset.scaleBarMm = bar;
  drawTriad();
  drawForceKey(ppm);
}

const SVG = 'http://www.w3.org/2000/svg';
function svg(tag, attributes, text) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

// The scene's axes as the camera sees them, the farthest drawn first; y, the mating axis, bold.
function drawTriad() {
  const triad = $('triad'), cx = 48, cy = 46, length = 28;
  const axes = [['x', [1, 0, 0]], ['y', [0, 1, 0]], ['z', [0, 0, 1]]].map(([name, a]) => {
    const d = new THREE.Vector3(...a).transformDirection(camera.matrixWorldInverse);
    return { name, x: d.x, y: -d.y, depth: d.z };
  }).sort((a, b) => a.depth - b.depth);
  triad.replaceChildren();
  for (const a of axes) {
    const bold = a.name === 'y';
    triad.appendChild(svg('line', { x1: cx, y1: cy, x2: cx + length * a.x, y2: cy + length * a.y,
      stroke: bold ? '#111' : '#555', 'stroke-width': bold ? 3 : 1.6, 'stroke-linecap': 'round' }));
    // The letter beyond the tip, or beside the centre where the axis points at the viewer.
    const n = Math.hypot(a.x, a.y), ux = n > 0.2 ? a.x / n : 0.7, uy = n > 0.2 ? a.y / n : -0.7;
    const reach = length * Math.max(n, 0.3) + 9;
    triad.appendChild(svg('text', { x: cx + reach * ux, y: cy + reach * uy + 4,
      'text-anchor': 'middle' }, a.name));
  }
  triad.appendChild(svg('text', { x: cx, y: 106, 'text-anchor': 'middle', class: 'caption' },
    'y: mating axis'));
}

// The resistances' values and the arrows' scale: a round force and the arrow it gets on screen at
// the orbit's centre, and the scale in newtons per mm of the scene.
function drawForceKey(ppm) {
  const values = $('force-values'), arrow = $('force-arrow');
  const scale = newtonsPerMm();
  arrow.replaceChildren();
  if (!view.state) {
    values.textContent = 'waiting for the first state';
    $('force-scale-text').textContent = '';
    $('force-scale-note').textContent = '';
    return;
  }
  const [fx, fy, fz] = joint() ? J.bodyForce(view.state, view.scene) : view.state.force;
  values.innerHTML = `<span class="axial">axial ${fmt(Math.abs(fy))} N</span> · ` +
    `<span class="radial">radial ${fmt(Math.hypot(fx, fz))} N</span>`;
  arrow.style.display = scale ? '' : 'none';  // an SVG element has no `hidden`
  if (!scale) {
    $('force-scale-text').textContent = view.history ? 'no force in this run' : 'no force so far';
    $('force-scale-note').textContent = '';
    return;
  }
  const reference = nice(70 / ppm * scale), px = Math.min(reference / scale * ppm, 106);
  arrow.setAttribute('width', Math.ceil(px) + 2);
  arrow.append(svg('line', { x1: 1, y1: 6, x2: px - 6, y2: 6, stroke: '#333', 'stroke-width': 2 }),
    svg('path', { d: `M${px} 6 L${px - 8} 2 L${px - 8} 10 Z`, fill: '#333' }));
  $('force-scale-text').textContent = `${round(reference)} N`;
  const cut = [Math.abs(fy), Math.hypot(fx, fz)].some((f) => f / scale > arrowLimit());
  $('force-scale-note').textContent = `arrow length: 1 mm = ${round(scale)} N` +
    (cut ? `; cut at ${round(arrowLimit() * scale)} N` : '');
}

function drawSpace(state) {
  const cv = $('space'), g = cv.getContext('2d');
  g.clearRect(0, 0, cv.width, cv.height);
  const known = (state.flags & F.FLAG_SPACE_KNOWN) !== 0;
  const note = $('space-note');
  if (!known) {
    note.textContent = 'this surface type does not describe its assembly space';
    return;
  }
  const pts = state.space;
  const off = [state.offsetX, state.offsetZ];
  let r = Math.hypot(...off);
  for (const p of pts) r = Math.max(r, Math.hypot(p[0], p[1]));
  r = r > 0 ? 1.15 * r : 1e-6;
  const cx = cv.width / 2, cy = cv.height / 2, k = (Math.min(cx, cy) - 6) / r;
  g.strokeStyle = '#bbb';
  g.beginPath(); g.moveTo(0, cy); g.lineTo(cv.width, cy); g.moveTo(cx, 0); g.lineTo(cx, cv.height);
  g.stroke();
  if (pts.length > 2) {
    g.fillStyle = 'rgba(31,158,137,0.25)';
    g.strokeStyle = '#1f9e89';
    g.beginPath();
    pts.forEach((p, i) => (i ? g.lineTo : g.moveTo).call(g, cx + k * p[0], cy - k * p[1]));
    g.closePath(); g.fill(); g.stroke();
  }
  g.fillStyle = '#c0392b';
  g.beginPath(); g.arc(cx + k * off[0], cy - k * off[1], 3.5, 0, 2 * Math.PI); g.fill();
  note.textContent = pts.length > 2
    ? `x right, z up; half-width ${fmt(1e6 * r)} µm; dot: the moving axis`
    : ((state.flags & F.FLAG_INTERFERENCE) ? 'empty: the parts interfere'
      : 'no section engaged');
}

// The trace runs over depth, or over the angle for a pair that mates by rotation.
const rotationalPair = () => Boolean(view.scene && view.scene.rotational);
const abscissa = (s) => (rotationalPair() ? s.angle * 180 / Math.PI : MM * s.depth);

function drawTrace() {
  const cv = $('trace'), g = cv.getContext('2d');
  g.clearRect(0, 0, cv.width, cv.height);
  const rows = view.history
    ? view.history.filter((h) => h.stage === 1).map((h) => [abscissa(h), Math.abs(h.force[1]),
      Math.hypot(h.force[0], h.force[2])])
    : view.trace;
  g.font = '11px system-ui';
  g.fillStyle = '#222';
  if (rows.length < 2 && view.others.size === 0) {
    g.fillText('waiting for the constrained stage', 8, 16);
    return;
  }
  // A comparison's scene that renders again is drawn solid only.
  const others = [...view.others].filter(([label]) => label !== Live.renderingLabel());
  let x0 = Infinity, x1 = -Infinity, y1 = 0;
  for (const r of [rows, ...others.map(([, other]) => other)]) {
    for (const [d, a, f] of r) { x0 = Math.min(x0, d); x1 = Math.max(x1, d); y1 = Math.max(y1, a, f); }
  }
  if (x1 <= x0) x1 = x0 + 1e-3;
  y1 = y1 > 0 ? 1.1 * y1 : 1;
  const L = 34, B = cv.height - 18, W = cv.width - L - 6, H = B - 6;
  const X = (d) => L + W * (d - x0) / (x1 - x0), Y = (f) => B - H * f / y1;
  g.strokeStyle = '#999'; g.strokeRect(L, 6, W, H);
  // The scenes before this one dashed and pale, this one's solid; each named in the legend.
  const legend = [];
  for (const [label, other] of others) {
    g.setLineDash([4, 3]);
    for (const [k, colour] of [[1, '#e6a39b'], [2, '#9db5e0']]) {
      g.strokeStyle = colour; g.beginPath();
      other.forEach((row, i) => (i ? g.lineTo : g.moveTo).call(g, X(row[0]), Y(row[k])));
      g.stroke();
    }
    g.setLineDash([]);
    legend.push(`- - ${label}`);
  }
  for (const [k, colour] of [[1, '#c0392b'], [2, '#1f5fbf']]) {
    g.strokeStyle = colour; g.beginPath();
    rows.forEach((row, i) => (i ? g.lineTo : g.moveTo).call(g, X(row[0]), Y(row[k])));
    g.stroke();
  }
  if (others.length) {
    legend.unshift(`— ${Live.renderingLabel() || 'this scene'}`);
    g.textAlign = 'right';
    legend.forEach((text, i) => g.fillText(text, cv.width - 10, 19 + 12 * i));
    g.textAlign = 'left';
  }
  // The top force inside the plot: four digits (1100 N) are wider than the margin.
  g.fillText(`${String(+y1.toPrecision(2))} N`, L + 3, 17);
  g.fillText('0', 24, B);
  g.fillText(`${x0.toFixed(1)}`, L, cv.height - 4);
  g.textAlign = 'right'; g.fillText(`${x1.toFixed(1)} ${rotationalPair() ? '° angle' : 'mm depth'}`, cv.width - 6, cv.height - 4);
  g.textAlign = 'left';
  if (view.state) {
    g.strokeStyle = '#000'; g.setLineDash([3, 3]); g.beginPath();
    g.moveTo(X(abscissa(view.state)), 6); g.lineTo(X(abscissa(view.state)), B); g.stroke();
    g.setLineDash([]);
  }
}

// --- controls ------------------------------------------------------------------------------
function setFactor(exponent) {
  view.factor = Math.pow(10, exponent);
  $('factor-value').textContent = view.factor >= 10 ? Math.round(view.factor) : view.factor.toFixed(1);
  displace(0); displace(1);
  companion.meshes.forEach((mesh, k) => displaceMesh(mesh, companion.geometry[k]));
  for (let k = 2; k < view.meshes.length; ++k) displace(k);
  view.holders.forEach((h, k) => shiftDeviation(k));
  if (view.labels.length) makeLabels();  // over the fixed parts, where this factor draws them
  if (view.state) place(view.state);
  requestRender();
}
$('factor').addEventListener('input', (e) => setFactor(parseFloat(e.target.value)));

let socket = null;
$('time').addEventListener('input', (e) => {
  const i = parseInt(e.target.value, 10);
  if (view.history && view.history[i]) $('time-value').textContent = `${view.history[i].time.toFixed(3)} s`;
  if (socket && socket.readyState === 1) socket.send(`seek ${i}`);
});

// Default exaggeration: the largest deviation drawn as 4 % of the (datum) inner part's radius.
function defaultFactor(info) {
  const parts = info.features && info.features.length
    ? info.features.flatMap((f) => [f.inner, f.outer]) : [info.inner, info.outer];
  const v = Math.max(...parts.map((p) => Math.max(Math.abs(p.variation_min_um),
    Math.abs(p.variation_max_um)))) * 1e-3;  // mm
  const radius = Math.max(info.inner.nominal_size_mm, 1) / 2;
  if (!(v > 0)) return 1;
  return Math.min(Math.max(0.04 * radius / v, 1), 10000);
}

// Everything drawn of the scene before: a sequence's next step (or another step asked for) draws
// its own parts from its scene message on, as the first scene is drawn.
const oneFeatureFactorHint = $('factor-hint').textContent;
function clearScene() {
  // A live view keeps the trace of the scene it leaves: a comparison's by its label, an edited
  // scene's as the one before the edit.
  if (document.body.dataset.live && view.trace.length > 1) {
    const label = document.body.dataset.live === 'compare' ? Live.renderingLabel() : 'before the edit';
    if (document.body.dataset.live === 'edit') view.others.clear();
    view.others.set(label, view.trace);
  }
  for (const group of [moving, fixed]) {
    emptyGroup(group);
    group.position.set(0, 0, 0);
    group.rotation.set(0, 0, 0);
  }
  for (const label of view.labels) label.element.remove();
  clearCompanion();
  Object.assign(view, { meshes: [null, null], geometry: [null, null], holders: [], labels: [],
    state: null, trace: [], history: null, finished: false, forcePeak: 0,
    forcePeakAny: 0, axialPeak: 0 });
  document.body.dataset.axialPeak = 0;
  document.body.dataset.parts = 0;
  $('features-panel').hidden = true;
  $('scrub').hidden = true;
  const placeholder = $('placeholder');
  if (placeholder) placeholder.remove();
  $('pressure-title').textContent = 'Contact pressure';
  $('space-title').textContent = 'Assembly space of the current section';
  $('factor-hint').textContent = oneFeatureFactorHint;
  // Nothing of the step before stands for this one's state until its first state frame.
  $('status').textContent = 'waiting for this step\'s first state';
  $('forces').replaceChildren();
  $('pressure-ticks').replaceChildren();
  $('pressure-range').textContent = '';
  for (const cv of [$('legend'), $('space')]) {
    cv.getContext('2d').clearRect(0, 0, cv.width, cv.height);
  }
  $('space-note').textContent = '';
  drawTrace();
}

function onScene(info) {
  if (view.scene) clearScene();
  view.scene = info;
  view.scenes += 1;
  document.body.dataset.scenes = view.scenes;
  $('title').textContent = info.scenario;
  $('subtitle').textContent = `${info.surface} · law ${info.law || '–'} · seed ${info.seed} · ` +
    `${info.inner.name} (${info.inner.rows}×${info.inner.columns}) in ${info.outer.name} ` +
    `(${info.outer.rows}×${info.outer.columns})`;
  if (info.features && info.features.length) showFeatures(info);
  const notes = [info.status, info.placeholder_note].filter((s) => s);
  $('note').hidden = notes.length === 0;
  $('note').textContent = notes.join('; ');
  if (info.placeholder_note) {
    const div = document.createElement('div');
    div.id = 'placeholder';
    div.textContent = info.placeholder_note;
    document.body.appendChild(div);
  }
  const e = Math.log10(defaultFactor(info));
  $('factor').value = e;
  setFactor(e);
  showSteps();
}

// --- sequence ------------------------------------------------------------------------------
function onSequence(info) {
  view.sequence = info;
  showSteps();
}

// A sequence: the shown step's label ("step 2 of 2: hub") under the sequence's name, and every
// step in the panel: what a finished one left (where its part was left across its axis, its
// depth, its axial resistance), the others running or waiting. A begun step other than the shown
// one is a button that asks the server for it.
function showSteps() {
  const seq = view.sequence;
  const shown = view.scene && Number.isInteger(view.scene.step) ? view.scene.step : null;
  $('steps-panel').hidden = !seq;
  $('step').hidden = !seq || shown === null;
  if (!seq) return;
  $('title').textContent = seq.scenario;
  const n = seq.steps.length;
  const state = (k) => (seq.steps[k].finished ? 'finished' : k === seq.newest ? 'running'
    : 'waiting');
  if (shown !== null && seq.steps[shown]) {
    $('step-label').textContent = `step ${shown + 1} of ${n}: ${seq.steps[shown].step}`;
    const newest = seq.steps[seq.newest];
    $('step-state').textContent = state(shown) + (shown !== seq.newest
      ? ` · the run is in step ${seq.newest + 1}: ${newest.step} (${state(seq.newest)})` : '');
    document.body.dataset.step = shown + 1;
  }
  const list = $('steps');
  list.replaceChildren();
  seq.steps.forEach((step, k) => {
    const item = document.createElement('li');
    item.className = k === shown ? 'shown' : '';
    let name;
    if (k !== shown && k <= seq.newest) {
      name = document.createElement('button');
      name.dataset.step = k;
      name.title = `show step ${k + 1}`;
      name.addEventListener('click', () => {
        if (socket && socket.readyState === 1) socket.send(`step ${k}`);
      });
    } else {
      name = document.createElement('b');
    }
    name.textContent = step.step;
    const details = document.createElement('span');
    details.className = 'hint';
    details.textContent = ` seed ${step.seed} · ${state(k)}` +
      (step.finished ? stepResult(step) : '');
    item.append(name, details);
    list.appendChild(item);
  });
}

// What a finished step left: its entry of the sequence's summary.json.
function stepResult(step) {
  const [x, z] = step.seated_offset_um, axial = step.axial_resistance_N;
  return `: part left at offset (${fmt(x)}, ${fmt(z)}) µm, ` +
    `depth ${fmt(step.final_depth_mm, 4)} mm` +
    (axial && axial.mean !== null && axial.mean !== undefined
      ? `; axial resistance mean ${fmt(axial.mean)} N, max ${fmt(axial.max)} N`
      : '; no constrained tick');
}

// The features of a several-feature scene in the panel: each one's colour, name, surface, parts
// (which body each is on) and placement, and the pressure map's and assembly space's feature.
function showFeatures(info) {
  const datum = info.features[0];
  $('subtitle').textContent = `${info.features.length} features · ${info.moving_body} (moving) on ` +
    `${info.fixed_body} (fixed) · seed ${info.seed}`;
  $('pressure-title').textContent = `Contact pressure on ${datum.inner.name} at ${datum.name}`;
  $('space-title').textContent = `Assembly space of ${datum.name} at the current section`;
  const list = $('features');
  list.replaceChildren();
  const mm = (x) => fmt(x, 4);
  info.features.forEach((f, i) => {
    const item = document.createElement('li');
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = cssColour(featureColour(i));
    const name = document.createElement('b');
    name.textContent = f.name;
    const side = (p) => `${p.name} ${p.body}` + (p.deviation_um.some((d) => d !== 0)
      ? ` (position deviation ${p.deviation_um.map((d) => d.toFixed(1)).join(', ')} µm)` : '') +
      (p.seat_um ? ` (seated at ${p.seat_um.map((d) => fmt(d)).join(', ')} µm by an earlier step)`
        : '');
    const where = i === 0 ? 'datum' : `at (${mm(f.at_mm[0])}, ${mm(f.at_mm[1])}) mm` +
      (f.engages_after_mm ? `, engages after ${mm(f.engages_after_mm)} mm` : '');
    const details = document.createElement('div');
    details.className = 'hint';
    details.textContent = `${f.surface.replace('fitfeel.surface.', '')}, law ${f.law}, ${where}` +
      (f.angle_deg ? `, turned ${mm(f.angle_deg)}°` : '') +
      ` · inner: ${side(f.inner)} · outer: ${side(f.outer)}`;
    item.append(swatch, name, details);
    list.appendChild(item);
  });
  $('features-note').textContent = `${info.moving_body}'s parts move with its pose, ` +
    `${info.fixed_body}'s stay; inner parts opaque, outer parts translucent; x, z of the joint frame.`;
  $('features-panel').hidden = false;
  $('factor-hint').textContent = 'Nominal shapes true to scale; the deviations V, the parts\' ' +
    'position deviations and the moving body\'s offset across the axis are drawn multiplied by ' +
    'this factor, its depth and twist true.';
}

function onHistory(rows) {
  view.history = rows;
  // The arrows' scale of the whole run: scrubbing does not change it.
  for (const row of rows) notePeak(row.stage, row.force);
  view.finished = true;
  $('scrub').hidden = false;
  const t = $('time');
  t.max = Math.max(rows.length - 1, 0);
  t.value = t.max;
  if (rows.length) $('time-value').textContent = `${rows[rows.length - 1].time.toFixed(3)} s`;
  drawTrace();
}

function connect() {
  socket = new WebSocket(`ws://${location.host}/ws`);
  socket.binaryType = 'arraybuffer';
  socket.onmessage = (event) => {
    if (typeof event.data === 'string') {
      const msg = JSON.parse(event.data);
      if (msg.type === 'scene' && msg.companion) onCompanion(msg);
      else if (msg.type === 'scene') onScene(msg);
      else if (msg.type === 'sequence') onSequence(msg);
      else if (msg.type === 'live') Live.onLive(msg, (text) => socket.send(text));
      return;
    }
    const kind = F.frameKind(event.data);
    if (kind === F.KIND_MESH && companion.pending > 0) addCompanionPart(F.readMesh(event.data));
    else if (kind === F.KIND_MESH) addPart(F.readMesh(event.data));
    else if (kind === F.KIND_HISTORY) onHistory(F.readHistory(event.data));
    else if (kind === F.KIND_STATE) {
      showState(F.readState(event.data));
      view.frames += 1;
      document.body.dataset.frames = view.frames;
      document.body.dataset.state = 'streaming';
    }
  };
  socket.onclose = () => {
    document.body.dataset.state = 'closed';
    $('status').textContent = 'disconnected: is fitfeel view still running?';
  };
}

Live.setUp();
connect();
