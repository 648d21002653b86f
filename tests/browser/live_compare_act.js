// The compare test's page actions (live_browser_test.sh, paper-case1-h7g6 --compare
// paper-case1-h7js6): the device renders A (H7/g6, which resists by the shaft's weight: 0.3 N);
// key B switches to the paper's H7/js6 pair (its sizes given as limits, so the button names the
// scene), whose form deviations press near the end of the stroke (10.3 N); key A
// switches back and the force follows. Gives true, or what it saw instead. (sleep and until: live_act_helpers.js)
(async () => {
  const body = document.body.dataset;
  const key = (k) => window.dispatchEvent(new KeyboardEvent('keydown', { key: k }));
  if (!(await until(() => body.rendering === 'A' && Number(body.frames) > 5, 60))) {
    return ['not rendering A', body.rendering, body.frames];
  }
  // A whole pass of A: the weight's friction only.
  const passes = Number(body.passes);
  if (!(await until(() => Number(body.passes) >= passes + 1, 30))) return ['no pass ended'];
  if (!(Number(body.axialPeak) > 0.2 && Number(body.axialPeak) < 1)) return ['A', body.axialPeak];

  key('b');  // when the part is out of contact: at the end of this pass
  if (!(await until(() => body.rendering === 'B', 30))) return ['B not rendered', body.rendering];
  if (!(await until(() => Number(body.axialPeak) > 8, 30))) return ['B force', body.axialPeak];
  // Both scenes drawn: the one rendering, and the other below it, named.
  if (body.companionParts !== '2' || !document.getElementById('companion-label').textContent
    .includes('paper-case1-h7g6')) {
    return ['the other scene not drawn', body.companionParts];
  }
  const buttons = [...document.querySelectorAll('#compare-buttons button')].map((b) => b.textContent);
  if (buttons.join() !== 'A: H7/g6,B: paper-case1-h7js6') return ['buttons', buttons];

  // Shift+A: at once, the part withdrawn.
  window.dispatchEvent(new KeyboardEvent('keydown', { key: 'A', shiftKey: true }));
  if (!(await until(() => body.rendering === 'A', 30))) return ['A not rendered', body.rendering];
  const back = Number(body.passes);
  if (!(await until(() => Number(body.passes) >= back + 1, 30))) return ['no pass of A'];
  if (!(Number(body.axialPeak) < 1)) return ['A after B', body.axialPeak];
  return true;
})()
