// The live edit test's page actions (live_browser_test.sh, fits-20mm-h7js6 with --edit): an edit
// the loader refuses shows its message and leaves the run as it was; then the shaft's class from
// js6 to k6, applied at once, changes the rendered force within 2 s of the click. Gives true, or
// what it saw instead.
(async () => {
  const $ = (id) => document.getElementById(id);
  const body = document.body.dataset;
  const input = (path) => document.querySelector(`[data-path="${path}"]`);
  if (!(await until(() => input('parts.shaft.size') && Number(body.frames) > 5, 60))) {
    return ['no edit form or frames', body.live, body.frames];
  }
  // The js6 scene resists by the shaft's weight only: about 0.3 N.
  if (!(await until(() => body.axialPeak > 0.2, 30))) return ['no js6 contact', body.axialPeak];
  const js6Peak = Number(body.axialPeak);
  if (js6Peak > 5) return ['js6 pushes too hard', js6Peak];

  // A friction the loader refuses: its message in the page, the scene untouched.
  const scenes = body.scenes, frames = Number(body.frames);
  input('model.friction').value = 'sticky';
  input('model.friction').dispatchEvent(new Event('input'));
  $('edit-apply-now').click();
  if (!(await until(() => body.editState === 'refused', 30))) return ['not refused', body.editState];
  const message = $('edit-status').textContent;
  if (!message.includes('model.friction') || !message.includes('sticky')) return ['message', message];
  await until(() => Number(body.frames) > frames + 30, 30);
  if (body.scenes !== scenes) return ['a refused edit replaced the scene', scenes, body.scenes];
  if (Number(body.axialPeak) > 5) return ['the refused edit changed the force', body.axialPeak];
  input('model.friction').value = input('model.friction').dataset.current;
  input('model.friction').dispatchEvent(new Event('input'));

  // js6 -> k6, at once: the part withdrawn, the k6 scene in, the force past 20 N (k6 presses).
  const shaft = input('parts.shaft.size');
  if (![...shaft.options].some((o) => o.value === 'k6')) return ['no k6 offered'];
  shaft.value = 'k6';
  shaft.dispatchEvent(new Event('change'));
  const clicked = performance.now();
  $('edit-apply-now').click();
  const changed = await until(() => Number(body.scenes) > Number(scenes) && body.axial > 20, 30);
  const latency = performance.now() - clicked;
  document.body.dataset.report = `the k6 force (${Number(body.axial).toFixed(0)} N) ` +
    `${latency.toFixed(0)} ms after the click`;
  if (!changed) return ['no k6 force', body.scenes, body.axial, $('edit-status').textContent];
  if (latency > 2000) return ['the k6 force came late (ms)', latency];
  // The trace draws the js6 scene's pass dashed, "before the edit".
  await sleep(1500);
  return true;
})()
