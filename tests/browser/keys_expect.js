// The keys over the 3D view, checked in the page of a finished one-feature run once its screenshot
// is taken (viewer_browser_test.sh passes this file to screenshot.mjs --expect-file): the pressure
// key says "no contact" at the run's first row and gives a range in MPa where the axial
// resistance peaks, the arrows' key gives both resistances and a scale in newtons, the axes are
// labelled, and the scale bar gives a length that shrinks as the view zooms in. Gives true, or
// what it found.
(async () => {
  const $ = (id) => document.getElementById(id);
  const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
  const drawn = () => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
  const frames = () => Number(document.body.dataset.frames);
  // The time slider to row i; the server answers with that row's state frame.
  async function seek(i) {
    const before = frames(), time = $('time');
    time.value = i;
    time.dispatchEvent(new Event('input'));
    for (let k = 0; k < 600 && frames() === before; ++k) await sleep(100);
    await drawn();
  }
  // The row where the parts press hardest, from the history on a connection of the test's own,
  // read with the page's frame reader.
  const F = await import('/frames.js');
  const rows = await new Promise((resolve, reject) => {
    const socket = new WebSocket(`ws://${location.host}/ws`);
    socket.binaryType = 'arraybuffer';
    socket.onmessage = (event) => {
      if (typeof event.data === 'string' || F.frameKind(event.data) !== F.KIND_HISTORY) return;
      resolve(F.readHistory(event.data));
      socket.close();
    };
    socket.onerror = reject;
  });
  let peak = 0;
  rows.forEach((row, i) => {
    if (Math.abs(row.force[1]) > Math.abs(rows[peak].force[1])) peak = i;
  });
  const problems = [];
  const check = (ok, what) => { if (!ok) problems.push(what); };

  await seek(0);
  const before = $('pressure-range').textContent;
  check(before === 'no contact', `pressure key at the first row: "${before}"`);
  await seek(peak);
  const after = $('pressure-range').textContent;
  check(/^0 to [0-9.e+]+ MPa; grey: no contact$/.test(after), `pressure key at row ${peak}: "${after}"`);
  const ticks = [...document.querySelectorAll('#pressure-ticks span')].map((s) => s.textContent);
  check(ticks.length === 3 && ticks[0] === '0' && ticks[2].endsWith(' MPa'), `pressure ticks ${ticks}`);

  const forces = $('force-values').textContent;
  check(/^axial [0-9.e+-]+ N · radial [0-9.e+-]+ N$/.test(forces), `force values "${forces}"`);
  const reference = $('force-scale-text').textContent, note = $('force-scale-note').textContent;
  check(/^[0-9.]+ N$/.test(reference), `reference arrow "${reference}"`);
  check(/^arrow length: 1 mm = [0-9.]+ N$/.test(note), `arrow scale "${note}"`);
  check($('force-arrow').querySelectorAll('line, path').length === 2, 'no reference arrow drawn');

  const labels = [...document.querySelectorAll('#triad text')].map((t) => t.textContent).sort();
  check(labels.join() === 'x,y,y: mating axis,z', `axis labels ${labels}`);

  const bar = () => [$('scale-text').textContent, $('scale-line').offsetWidth];
  const [text, width] = bar();
  check(/^[0-9.]+ (mm|µm)$/.test(text) && width >= 40 && width <= 160, `scale bar "${text}", ${width} px`);
  const canvas = document.querySelector('#scene > canvas');
  for (let i = 0; i < 30; ++i) {
    canvas.dispatchEvent(new WheelEvent('wheel', { deltaY: -100, bubbles: true, cancelable: true }));
  }
  await drawn();
  const [zoomedText, zoomedWidth] = bar();
  check(parseFloat(zoomedText) < parseFloat(text) || zoomedText.endsWith('µm'),
    `scale bar after zooming in "${zoomedText}" (before "${text}")`);
  check(zoomedWidth >= 40 && zoomedWidth <= 160, `scale bar after zooming in ${zoomedWidth} px`);
  return problems.length === 0 || problems;
})()
