// The live panel of `fitfeel view --edit` and `--compare` (the panel message, `type` "live"):
// an edited scene's fields (sizes as ISO 286 classes, a fit that sets both, form and texture
// values, friction, seed), what the server understood of the last edit or why it refused it,
// and the buttons that apply it when the part is out of contact or at once, or save the scene;
// a comparison's two scenes, which one the device renders, and the keys A and B that switch.
const $ = (id) => document.getElementById(id);

const live = { msg: null, yaml: null, send: null, inputs: new Map() };

function option(select, value, text) {
  const o = document.createElement('option');
  o.value = value;
  o.textContent = text || value;
  select.appendChild(o);
  return o;
}

// The form, made again whenever the scene it edits changed (an edit prepared or swapped in).
function buildForm(msg) {
  const form = $('edit-fields');
  form.replaceChildren();
  live.inputs.clear();
  const row = (text, input) => {
    const label = document.createElement('label');
    label.textContent = text;
    label.htmlFor = input.id = `edit-${form.children.length}`;
    form.append(label, input);
  };
  if (msg.fits.length) {
    const select = document.createElement('select');
    option(select, '', msg.fit ? `${msg.fit} (as drawn)` : 'choose a fit');
    for (const fit of msg.fits) option(select, fit);
    select.addEventListener('change', () => {
      if (!select.value) return;
      const [hole, shaft] = select.value.split('/');
      for (const [path, input] of live.inputs) {
        if (!input.classList.contains('iso-class')) continue;
        const want = /^[A-Z]/.test(input.dataset.current) ? hole : shaft;
        if ([...input.options].some((o) => o.value === want)) input.value = want;
        markChanged(path);
      }
    });
    row('fit', select);
  }
  for (const field of msg.fields) {
    let input;
    if (field.classes) {
      // An ISO 286 size: its nominal kept, the class chosen among those the standard defines.
      input = document.createElement('select');
      input.className = 'iso-class';
      for (const c of field.classes) option(input, c);
      input.value = field.class;
      input.dataset.current = field.class;
      input.dataset.nominal = field.nominal;
    } else {
      input = document.createElement('input');
      input.type = 'text';
      input.size = 10;
      input.value = field.value;
      input.dataset.current = field.value;
    }
    input.dataset.path = field.path;
    input.addEventListener('input', () => markChanged(field.path));
    input.addEventListener('change', () => markChanged(field.path));
    row(field.classes ? `${field.label} (${field.nominal})` : field.label, input);
    live.inputs.set(field.path, input);
  }
}

function markChanged(path) {
  const input = live.inputs.get(path);
  input.classList.toggle('changed', input.value !== input.dataset.current);
}

// The changed fields as the scenario's key paths and values.
function edits() {
  const out = {};
  for (const [path, input] of live.inputs) {
    if (input.value === input.dataset.current) continue;
    out[path] = input.classList.contains('iso-class') ? `${input.dataset.nominal} ${input.value}`
      : input.value;
  }
  return out;
}

function submit(apply) {
  const changed = edits();
  if (!Object.keys(changed).length && apply !== 'check') {
    $('edit-status').textContent = 'nothing changed';
    return;
  }
  live.send(JSON.stringify({ type: 'edit', edits: changed, apply }));
  $('edit-status').textContent = apply === 'check' ? 'checking...' : 'sent';
  document.body.dataset.editState = 'sent';
}

function save() {
  const blob = new Blob([live.msg.yaml], { type: 'application/x-yaml' });
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = `${live.msg.scene}-edited.yaml`;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

function showEdit(msg) {
  const e = msg.edit || {};
  const state = e.state || '';
  document.body.dataset.editState = state;
  const status = $('edit-status');
  status.className = state === 'refused' ? 'warning' : 'hint';
  const text = {
    valid: 'valid: apply it to feel it',
    preparing: 'preparing the edited scene...',
    swapping: `prepared in ${Math.round(e.prepare_ms)} ms; withdrawing the part and swapping it in`,
    refused: `refused (the running scene is unchanged): ${e.message}`,
    applied: `applied: the device renders the edited scene (prepared in ${Math.round(e.prepare_ms)} ms)`,
  }[state] || (state.startsWith('waiting') ? `prepared in ${Math.round(e.prepare_ms)} ms; ` +
    'swapped in when the part is out of contact' : '');
  status.textContent = text;
  $('edit-described').textContent = e.described || '';
  $('edit-understood').hidden = !e.described;
  $('edit-now').disabled = !msg.pending;
}

function selectScene(k, now) {
  live.send(JSON.stringify({ type: 'select', scene: k, now }));
}

function showCompare(msg) {
  const c = msg.compare;
  const buttons = $('compare-buttons');
  if (buttons.children.length !== c.scenes.length) {
    buttons.replaceChildren();
    c.scenes.forEach((s, k) => {
      const b = document.createElement('button');
      b.dataset.scene = k;
      b.addEventListener('click', () => selectScene(k, $('compare-now').checked));
      buttons.appendChild(b);
    });
  }
  c.scenes.forEach((s, k) => {
    const b = buttons.children[k];
    b.textContent = `${s.label}: ${s.fit || s.scene}`;
    b.title = `${s.scene} (${s.file}), prepared in ${Math.round(s.prepare_ms)} ms`;
    b.classList.toggle('rendering', k === c.rendering);
    b.classList.toggle('selected', k === c.selected && k !== c.rendering);
  });
  const r = c.scenes[c.rendering], sel = c.scenes[c.selected];
  $('compare-state').textContent = `the device renders ${r.label} (${r.scene})` +
    (c.selected !== c.rendering ? `; ${sel.label} follows when the part is out of contact` : '');
  document.body.dataset.rendering = r.label;
}

// Keys A and B (Shift: at once) select a comparison's scene.
function onKey(event) {
  if (!live.msg || live.msg.mode !== 'compare') return;
  if (event.target && /^(INPUT|SELECT|TEXTAREA)$/.test(event.target.tagName)) return;
  const k = { a: 0, b: 1 }[event.key.toLowerCase()];
  if (k === undefined) return;
  selectScene(k, event.shiftKey || $('compare-now').checked);
}

export function onLive(msg, send) {
  live.send = send;
  live.msg = msg;
  $('live-panel').hidden = false;
  document.body.dataset.live = msg.mode;
  document.body.dataset.passes = msg.passes;
  $('live-passes').textContent = `${msg.passes} passes, ${msg.swaps} scenes swapped in`;
  $('edit-panel').hidden = msg.mode !== 'edit';
  $('compare-panel').hidden = msg.mode !== 'compare';
  if (msg.mode === 'compare') {
    showCompare(msg);
    return;
  }
  if (msg.yaml !== live.yaml) {
    live.yaml = msg.yaml;
    buildForm(msg);
  }
  // The scenario keeps its name; the title says it renders as edited (and the fit it has now).
  if (msg.swaps > 0) {
    $('title').textContent = `${msg.scene} (edited${msg.fit ? `: ${msg.fit}` : ''})`;
  }
  showEdit(msg);
}

// The scene the device renders, for the trace's legend: a comparison's label and fit.
export function renderingLabel() {
  if (!live.msg || live.msg.mode !== 'compare') return null;
  const s = live.msg.compare.scenes[live.msg.compare.rendering];
  return `${s.label}: ${s.fit || s.scene}`;
}

export function setUp() {
  $('edit-check').addEventListener('click', () => submit('check'));
  $('edit-apply').addEventListener('click', () => submit('free'));
  $('edit-apply-now').addEventListener('click', () => submit('now'));
  $('edit-now').addEventListener('click', () => live.send(JSON.stringify({ type: 'apply' })));
  $('edit-save').addEventListener('click', save);
  window.addEventListener('keydown', onKey);
}
