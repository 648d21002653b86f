// Loads a page in headless Chromium over the DevTools protocol (no npm packages: Node's own
// WebSocket, --experimental-websocket on Node 20), waits until the page has received frames,
// then saves a screenshot.
//
// node --experimental-websocket screenshot.mjs URL OUT.png [--min-frames N] [--timeout S]
//      [--size WxH] [--eval JS] [--act-file FILE] [--expect JS | --expect-file FILE]
// --eval runs JS in the page once the frames came (e.g. moves the time slider) and waits for
// one more frame. --act-file FILE: JavaScript (awaited) that acts on the page and must give true
// before the picture is taken (a live view's edits). --expect JS, evaluated in the page once the picture is drawn, must give true
// (anything else is reported); --expect-file reads that JS from FILE. Exit 0 on success, 1 with
// a message otherwise.
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
const [url, out] = args;
const minFrames = Number(option('--min-frames', '1'));
const timeoutMs = 1000 * Number(option('--timeout', '90'));
const [width, height] = option('--size', '1280x800').split('x').map(Number);
const script = option('--eval', '');
const expectFile = option('--expect-file', '');
const expectation = expectFile ? readFileSync(expectFile, 'utf8') : option('--expect', '');
const actFile = option('--act-file', '');
const action = actFile ? readFileSync(actFile, 'utf8') : '';
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';

const profile = mkdtempSync(join(tmpdir(), 'fitfeel-chromium-'));
const browser = spawn(chromium, [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--disable-dev-shm-usage', '--enable-unsafe-swiftshader', `--user-data-dir=${profile}`,
  '--remote-debugging-port=0', 'about:blank'], { stdio: 'ignore' });

const deadline = Date.now() + timeoutMs;
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
function fail(message) {
  console.error(`screenshot: ${message}`);
  cleanUp();
  process.exit(1);
}
function cleanUp() {
  try { browser.kill('SIGKILL'); } catch (e) { /* already gone */ }
  try { rmSync(profile, { recursive: true, force: true }); } catch (e) { /* best effort */ }
}
setTimeout(() => fail(`timed out after ${timeoutMs / 1000} s`), timeoutMs).unref();

const portFile = join(profile, 'DevToolsActivePort');
while (!existsSync(portFile) || readFileSync(portFile, 'utf8').split('\n').length < 2) {
  if (Date.now() > deadline) fail('Chromium did not open its DevTools port');
  if (browser.exitCode !== null) fail(`Chromium exited with ${browser.exitCode}`);
  await sleep(100);
}
const [port, path] = readFileSync(portFile, 'utf8').split('\n');
if (process.env.DEBUG) console.error('devtools', port, path);
const ws = new WebSocket(`ws://127.0.0.1:${port}${path}`);
await new Promise((resolve, reject) => { ws.onopen = resolve; ws.onerror = reject; });
let nextId = 1;
const pending = new Map();
ws.onmessage = (event) => {
  const msg = JSON.parse(event.data);
  if (msg.id && pending.has(msg.id)) {
    const { resolve, reject } = pending.get(msg.id);
    pending.delete(msg.id);
    if (msg.error) reject(new Error(JSON.stringify(msg.error))); else resolve(msg.result);
  }
};
const send = (method, params = {}, sessionId) => new Promise((resolve, reject) => {
  const id = nextId++;
  pending.set(id, { resolve, reject });
  ws.send(JSON.stringify({ id, method, params, ...(sessionId ? { sessionId } : {}) }));
});

const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
const page = (method, params) => send(method, params, sessionId);
const evaluate = async (expression) => (await page('Runtime.evaluate',
  { expression, returnByValue: true, awaitPromise: true })).result.value;
await page('Emulation.setDeviceMetricsOverride',
  { width, height, deviceScaleFactor: 1, mobile: false });
await page('Page.navigate', { url });
if (process.env.DEBUG) console.error('navigated');

const frames = () => evaluate('document.body ? Number(document.body.dataset.frames || 0) : 0');
async function waitFrames(count) {
  for (let n = await frames(); n < count; n = await frames()) {
    if (process.env.DEBUG) console.error('frames', n, await evaluate('document.body && document.body.dataset.state'));
    if (Date.now() > deadline) fail(`fewer than ${count} frames arrived`);
    await sleep(100);
  }
}
await waitFrames(minFrames);
if (script) {
  const before = await frames();
  await evaluate(script);
  await waitFrames(before + 1);
}
if (action) {
  const result = await evaluate(action);
  if (result !== true) fail(`the page gives ${JSON.stringify(result)} for --act-file ${actFile}`);
  const report = await evaluate('document.body.dataset.report || ""');
  if (report) console.log(`screenshot: the page reports ${report}`);
}
// Two animation frames: the last state is drawn before the picture is taken.
await evaluate('new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)))');
const { data } = await page('Page.captureScreenshot', { format: 'png' });
writeFileSync(out, Buffer.from(data, 'base64'));
if (expectation) {
  const result = await evaluate(expectation);
  if (result !== true) fail(`the page gives ${JSON.stringify(result)} for ${expectation}`);
}
console.log(`screenshot: ${out} after ${await frames()} frames`);
ws.close();
cleanUp();
process.exit(0);
