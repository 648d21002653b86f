// The live tests' helpers, put before each test's actions (live_browser_test.sh): a pause, and a
// wait for a condition that gives its last answer once the bound (s) has passed.
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const until = async (test, seconds) => {
  for (const end = performance.now() + 1000 * seconds; performance.now() < end; await sleep(10)) {
    if (test()) return true;
  }
  return test();
};
