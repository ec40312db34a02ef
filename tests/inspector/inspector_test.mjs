// Browser test of the bsc inspector (web/inspector) in headless Chromium, driven by playwright-core.
//
//   node inspector_test.mjs live --program <mcs> --out <dir> [--node-modules <dir>] [--web-root <dir>]
//       runs `<mcs> --inspect 0 --commands [--web-root <dir>]`, opens the page it serves, pushes ON_P and ESTOP_P
//       on the page and checks the page and the program agree on the configuration.
//   node inspector_test.mjs system --program <production_cell> --out <dir> [--node-modules <dir>] [--web-root <dir>]
//       runs `<production_cell> --inspect 0 --commands --period-ms 20`, opens the page, checks one
//       box per actor and one edge per pair of linked actors against the program's /info, follows
//       the actors' states, shows another actor's chart, pauses and single-steps the cell, and sets
//       an operator's input and refuses one a link drives.
//   node inspector_test.mjs replay-system --folder <dir> --web-root <dir> --out <dir> [--node-modules <dir>]
//       opens a system's recording (`production_cell --trace <dir>`: system.json and one .bsctrace
//       per actor) from file://, checks the boxes and edges against system.json, shows the robot,
//       and at several timeline positions checks that every other actor's box shows that actor's
//       leaf states at the time of the robot's record, worked out here from its own trace.
//   node inspector_test.mjs replay --trace <file> --web-root <dir> --out <dir> [--node-modules <dir>]
//                                  [--python <python3>]
//       opens <web-root>/index.html from file:// (with no browser flag: a user's browser has
//       none), loads the trace and checks the configuration the page shows at several timeline
//       positions against the trace's own records; then the same for a trace that starts at a
//       dictionary followed by configuration records. The page's reader must describe both as
//       tools/bsc-trace does.
//
// Exits 0 when every check ran and passed, 77 (skipped) when Chromium or playwright-core is
// missing or the web root has no elk.bundled.js (the build copies it from web/node_modules),
// 1 otherwise. Everything it starts is stopped on the way out, also on failure or timeout.

import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import vm from 'node:vm';
import { createRequire } from 'node:module';
import { fileURLToPath, pathToFileURL } from 'node:url';

const SKIP = 77;
const CHROMIUM = '/usr/bin/chromium';
const TIMEOUT_MS = 90_000;
const WAIT_MS = 15_000;
const here = path.dirname(fileURLToPath(import.meta.url));
const BSC_TRACE = path.resolve(here, '../../tools/bsc-trace');
const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

// ---- Arguments ------------------------------------------------------------------------------

function parseArgs(argv) {
  const [mode, ...rest] = argv;
  const options = {};
  for (let i = 0; i < rest.length; i += 2) {
    if (!rest[i].startsWith('--') || i + 1 >= rest.length) usage(`bad argument '${rest[i]}'`);
    options[rest[i].slice(2)] = rest[i + 1];
  }
  const needed = { live: ['program', 'out'], system: ['program', 'out'], 'replay-system': ['folder', 'web-root', 'out'], replay: ['trace', 'web-root', 'out'] }[mode];
  if (!needed) usage(`unknown mode '${mode ?? ''}'`);
  for (const name of needed) if (!options[name]) usage(`--${name} is missing`);
  options['node-modules'] ??= path.resolve(here, '../../web/node_modules');
  options.python ??= 'python3';
  return { mode, options };
}

function usage(why) {
  console.error(`inspector_test: ${why}
usage: node inspector_test.mjs live --program <mcs> --out <dir> [--node-modules <dir>] [--web-root <dir>]
       node inspector_test.mjs system --program <production_cell> --out <dir> [--node-modules <dir>] [--web-root <dir>]
       node inspector_test.mjs replay-system --folder <dir> --web-root <dir> --out <dir> [--node-modules <dir>]
       node inspector_test.mjs replay --trace <file> --web-root <dir> --out <dir> [--node-modules <dir>] [--python <python3>]`);
  process.exit(1);
}

// ---- Processes, cleanup and the time limit --------------------------------------------------

const started = new Set(); // child processes still to stop
let browser = null;

// Each program runs in a process group of its own, so that a signal reaches whatever it started too.
function signal(child, name) {
  try {
    process.kill(-child.pid, name);
  } catch {
    child.kill(name);
  }
}

function killAll() {
  for (const child of started) signal(child, 'SIGKILL');
}

// Playwright's own exit hook kills the browser; the program is ours to kill.
process.on('exit', killAll);
for (const name of ['SIGINT', 'SIGTERM', 'SIGHUP']) {
  process.on(name, () => {
    console.error(`inspector_test: ${name}, stopping`);
    process.exit(1);
  });
}
const deadline = setTimeout(() => {
  console.error(`inspector_test: not done after ${TIMEOUT_MS / 1000} s, giving up`);
  process.exit(1);
}, TIMEOUT_MS);

const exited = (child) =>
  child.exitCode !== null || child.signalCode !== null
    ? Promise.resolve()
    : new Promise((resolve) => child.once('exit', () => resolve()));
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// Closing standard input asks the program to leave; SIGTERM, then SIGKILL, if it does not.
async function stopProgram(child) {
  if (!started.has(child)) return;
  child.stdin.end();
  for (const name of ['SIGTERM', 'SIGKILL']) {
    if (await Promise.race([exited(child).then(() => true), sleep(2000).then(() => false)])) break;
    signal(child, name);
  }
  await Promise.race([exited(child), sleep(2000)]);
  started.delete(child);
}

// ---- Checks ---------------------------------------------------------------------------------

// Thrown when the page cannot be tested here; main reports it as skipped (77), never passed.
class Skip extends Error {}

let passed = 0;
function check(condition, what) {
  if (!condition) throw new Error(`check failed: ${what}`);
  ++passed;
  console.log(`ok ${passed} - ${what}`);
}

async function waitFor(page, predicate, arg, what) {
  try {
    await page.waitForFunction(predicate, arg, { timeout: WAIT_MS, polling: 50 });
    return true;
  } catch {
    console.error(`inspector_test: waited ${WAIT_MS / 1000} s for ${what}`);
    return false;
  }
}

const sameSet = (a, b) => a.length === b.length && [...a].sort().join('\n') === [...b].sort().join('\n');

// The states the drawing marks active, as a check independent of window.bscInspector.
const drawnActive = (page) => page.$$eval('g[data-state].active', (gs) => gs.map((g) => g.dataset.state));

// ---- Live -----------------------------------------------------------------------------------

// Starts `program --inspect 0 --commands [--web-root <dir>] ...extra` and waits for the address it
// prints ("inspect: http://127.0.0.1:<port>/"); skips when its web root has no layout engine.
async function startProgram(options, extra = []) {
  const webRoot = options['web-root'] ? ['--web-root', path.resolve(options['web-root'])] : [];
  const program = spawn(options.program, ['--inspect', '0', '--commands', ...webRoot, ...extra], { stdio: ['pipe', 'pipe', 'pipe'], detached: true });
  started.add(program);
  const run = { program, stdout: '', url: null };
  program.stdout.setEncoding('utf8');
  program.stdout.on('data', (text) => (run.stdout += text));
  program.stderr.setEncoding('utf8');
  program.stderr.on('data', (text) => process.stderr.write(text.replace(/^/gm, 'program: ')));
  let failed = false; // could not be started at all
  program.on('error', (e) => {
    failed = true;
    started.delete(program);
    console.error(`inspector_test: ${options.program}: ${e.message}`);
  });
  program.stdin.on('error', () => {}); // closing it after the program has gone
  run.outputLine = async (pattern) => {
    for (let waited = 0; waited < WAIT_MS; waited += 50) {
      const line = run.stdout.split('\n').find((l) => pattern.test(l));
      if (line) return line;
      await sleep(50);
    }
    return null;
  };
  for (let waited = 0; !run.url && waited < WAIT_MS; waited += 50) {
    run.url = /inspect: (http:\/\/\S+)/.exec(run.stdout)?.[1] ?? null;
    if (!run.url && (failed || program.exitCode !== null)) break;
    if (!run.url) await sleep(50);
  }
  check(run.url !== null, `the program printed its inspector's address (${run.url ?? 'none'})`);
  // Without its layout engine the page draws no transitions: nothing to test it against.
  const elk = await fetch(new URL('elk.bundled.js', run.url)).catch((e) => ({ ok: false, status: e.message }));
  if (!elk.ok) throw new Skip(`the program's web root has no elk.bundled.js (${elk.status}; npm install in web/, then build)`);
  return run;
}

async function live(page, options, out) {
  const run = await startProgram(options);
  const { program, url, outputLine } = run;
  try {
    await page.goto(url);
    check(await waitFor(page, () => window.bscInspector?.ready, null, 'the chart'), 'the page drew the chart');
    check((await page.evaluate(() => window.bscInspector.mode)) === 'live', 'the page runs in live mode');
    const active = () => page.evaluate(() => window.bscInspector.active());
    check(
      await waitFor(page, () => window.bscInspector.active().includes('Off'), null, 'Off active'),
      'the page shows Off active at the start',
    );

    await page.click('[data-event="ON_P"]');
    const on = await waitFor(
      page,
      () => ['On', 'Auto', 'Mem'].every((s) => window.bscInspector.active().includes(s)) && !window.bscInspector.active().includes('Off'),
      null,
      'On Auto Mem active',
    );
    check(on, `after ON_P the page shows On, Auto, Mem active and Off not (${(await active()).join(' ')})`);
    const drawn = await drawnActive(page);
    check(['On', 'Auto', 'Mem'].every((s) => drawn.includes(s)) && !drawn.includes('Off'), `the drawing marks them (${drawn.join(' ')})`);
    const line = await outputLine(/ON_P.*MCS On Auto Mem/);
    check(line !== null, `the program printed the push: '${(line ?? '').trim()}'`);
    // The answer may come after the poll that showed the push's records.
    await waitFor(page, () => /^ok\b/.test(document.getElementById('status').textContent.trim()), null, 'the answer');
    const status = (await page.textContent('#status')).trim();
    check(/^ok\b/.test(status), `the status line shows the command's answer ('${status}')`);
    check(
      await waitFor(page, () => [...document.querySelectorAll('#log .line')].some((l) => l.textContent.includes('dispatch ON_P')), null, 'the log line'),
      'the log shows the dispatch',
    );

    await page.click('[data-event="ESTOP_P"]');
    const estop = await waitFor(
      page,
      () => window.bscInspector.active().includes('Estop') && !window.bscInspector.active().includes('On'),
      null,
      'Estop active',
    );
    check(estop, `after ESTOP_P the page shows Estop active and On not (${(await active()).join(' ')})`);
    check((await outputLine(/ESTOP_P.*MCS Estop/)) !== null, 'the program printed the emergency stop');
    // The picture shows the steady page, after the fired transition's pulse and the changed
    // value's highlight (1.5 s) have faded; the fired transition stays marked.
    await page.mouse.move(0, 0);
    await sleep(1700);
    await page.screenshot({ path: path.join(out, 'inspector_live.png') });
  } finally {
    await stopProgram(program);
  }
}

// ---- A system -------------------------------------------------------------------------------

async function system(page, options, out) {
  const run = await startProgram(options, ['--period-ms', '20']);
  const { url, outputLine } = run;
  try {
    const info = await (await fetch(new URL('info', url))).json();
    check(info.system === true && info.actors.length === 10, `the program describes a system of ${info.actors?.length} actors`);
    await page.goto(url);
    check(await waitFor(page, () => window.bscInspector?.system && window.bscInspector.ready, null, 'the system'), 'the page drew the system and a chart');
    const boxes = await page.$$eval('#system-svg .actor', (gs) => gs.map((g) => g.dataset.name));
    check(sameSet(boxes, info.actors.map((a) => a.name)), `one box per actor (${boxes.join(' ')})`);
    const pairs = new Set(info.links.map((l) => `${l.from}>${l.to}`));
    const drawn = await page.$$eval('#system-svg .link', (gs) => gs.map((g) => `${g.dataset.from}>${g.dataset.to}`));
    check(drawn.length === pairs.size && drawn.every((p) => pairs.has(p)), `one edge per pair of linked actors (${drawn.length} for ${info.links.length} links)`);
    const motor = info.links.findIndex((l) => info.actors[l.from].name === 'feed_belt' && l.from_channel === 'motor');
    const motorEdge = await page.$eval(
      `#system-svg .link[data-from="${info.links[motor].from}"][data-to="${info.links[motor].to}"]`,
      (g) => g.dataset.channels,
    );
    check(motorEdge.split(', ').includes('motor'), `the feed belt's edge to its plant names the motor ('${motorEdge}')`);

    // Every actor's box shows its configuration; the controllers move as bricks arrive.
    check(
      await waitFor(page, () => window.bscInspector.actors().every((a) => a.states), null, 'every box filled'),
      'every actor box shows its leaf states',
    );
    const at = async (name) => (await page.evaluate(() => window.bscInspector.actors())).find((a) => a.name === name).states;
    const robotFirst = await at('robot');
    check(
      await waitFor(page, (first) => window.bscInspector.actors().find((a) => a.name === 'robot').states !== first, robotFirst, 'the robot moves'),
      `the robot's box follows its states ('${robotFirst}', then '${await at('robot')}')`,
    );
    check((await page.evaluate(() => window.bscInspector.selected)) === 0, 'the first actor is shown at the start');

    // Another actor's chart: its box selected, its chart drawn with the box's states active.
    await page.click('#system-svg .actor[data-name="press"]');
    check(
      await waitFor(page, () => window.bscInspector.selected === 3 && window.bscInspector.dictionary.chart === 'PressActor', null, 'the press'),
      'a click on the press shows its chart',
    );
    check((await page.textContent('#chart-name')).trim() === 'press · PressActor', 'the chart is named after the actor');
    await waitFor(page, () => document.querySelectorAll('#chart-svg g[data-state]').length > 0, null, 'the press drawn');
    check(
      await page.$eval('#system-svg .actor[data-name="press"]', (g) => g.classList.contains('selected')),
      'the press box is marked selected',
    );

    // Paused, the cell takes one step per step command: one more cycle of the press.
    await page.click('#pause');
    check((await outputLine(/page: pause -> ok paused/)) !== null, 'the program printed the pause');
    await waitFor(page, () => document.getElementById('run-state').textContent === 'paused', null, 'the paused badge');
    await sleep(300); // the records of a step in flight
    const cycles = () => page.evaluate(() => window.bscInspector.records.filter((r) => r.typeName === 'cycle').length);
    const before = await cycles();
    await sleep(400);
    check((await cycles()) === before, `paused, the press runs no cycle (${before})`);
    await page.click('#step');
    check(await waitFor(page, (n) => window.bscInspector.records.filter((r) => r.typeName === 'cycle').length === n + 1, before, 'one cycle'), 'one step: one cycle');
    await sleep(400);
    check((await cycles()) === before + 1, 'and no more');
    const leaves = await at('press');
    const shown = await drawnActive(page);
    check(leaves.split(' ').every((s) => shown.includes(s)), `the chart marks the box's states active (${leaves}; ${shown.join(' ')})`);

    // The operator's switch is set from the page; an input that a link drives is refused.
    await page.selectOption('#set-member', 'on');
    await page.fill('#set-value', 'false');
    await page.click('#set-form button[type="submit"]');
    check((await outputLine(/page: set press on false -> ok press\.on = false/)) !== null, 'the program set the press\u2019s switch');
    await page.selectOption('#set-member', 'loaded');
    await page.fill('#set-value', 'true');
    await page.click('#set-form button[type="submit"]');
    check(
      await waitFor(page, () => /driven by the link from robot\.press_loaded/.test(document.getElementById('status').textContent), null, 'the refusal'),
      `a linked input is refused, the link named ('${(await page.textContent('#status')).trim()}')`,
    );
    await page.click('#resume');
    check((await outputLine(/page: resume -> ok running/)) !== null, 'the program runs again');
    await page.mouse.move(0, 0);
    await sleep(1700);
    await page.screenshot({ path: path.join(out, 'inspector_system.png') });
  } finally {
    await stopProgram(run.program);
  }
}

// ---- A system's recording -------------------------------------------------------------------

// The leaf states after each record of a trace: the active states that are no other active
// state's parent, by name, sorted as the page sorts them (by number).
function leafStates(BscTrace, trace) {
  const d = trace.reader.dictionary;
  return configurations(BscTrace, trace.records).map((active) => {
    const parents = new Set(active.map((n) => d.states[n]?.parent));
    return active
      .filter((n) => !parents.has(n) && d.states[n] && d.states[n].kind !== BscTrace.StateKind.top)
      .sort((a, b) => a - b)
      .map((n) => d.stateName(n))
      .join(' ');
  });
}

async function replaySystem(page, options, out) {
  const webRoot = path.resolve(options['web-root']);
  if (!fs.existsSync(path.join(webRoot, 'elk.bundled.js'))) throw new Skip(`no elk.bundled.js in ${webRoot} (npm install in web/, then build)`);
  const BscTrace = loadReader(webRoot);
  const folder = path.resolve(options.folder);
  const info = JSON.parse(fs.readFileSync(path.join(folder, 'system.json'), 'utf8'));
  check(info.system === true && info.actors.length > 1, `system.json describes ${info.actors.length} actors`);
  const traces = new Map();
  for (const a of info.actors) {
    const trace = readTrace(BscTrace, fs.readFileSync(path.join(folder, `${a.name}.bsctrace`)));
    trace.leaves = leafStates(BscTrace, trace);
    traces.set(a.name, trace);
  }
  check([...traces.values()].every((t) => t.reader.missing === 0 && t.reader.skippedBytes === 0 && t.records.length > 0), 'every actor\u2019s trace is whole');

  await page.goto(pathToFileURL(path.join(webRoot, 'index.html')).href);
  await page.waitForSelector('#trace-file', { state: 'attached', timeout: WAIT_MS });
  const files = fs.readdirSync(folder).filter((n) => n === 'system.json' || n.endsWith('.bsctrace'));
  await page.setInputFiles('#trace-file', files.map((n) => path.join(folder, n)));
  check(await waitFor(page, () => window.bscInspector?.system && window.bscInspector.ready, null, 'the system'), 'the page drew the recorded system');
  const boxes = await page.$$eval('#system-svg .actor', (gs) => gs.map((g) => g.dataset.name));
  check(sameSet(boxes, info.actors.map((a) => a.name)), `one box per actor (${boxes.length})`);
  const pairs = new Set(info.links.map((l) => `${l.from}>${l.to}`));
  check((await page.$$eval('#system-svg .link', (gs) => gs.length)) === pairs.size, `one edge per pair of linked actors (${pairs.size})`);
  await waitFor(page, () => document.getElementById('status').textContent.startsWith('system.json:'), null, 'every file read');
  const status = (await page.textContent('#status')).trim();
  const total = [...traces.values()].reduce((n, t) => n + t.records.length, 0);
  check(status === `system.json: ${info.actors.length} actors, ${total} records`, `the page read every record ('${status}')`);

  // At the end, every box shows its actor's last leaf states.
  const boxStates = async () => Object.fromEntries((await page.evaluate(() => window.bscInspector.actors())).map((a) => [a.name, a.states]));
  let shown = await boxStates();
  check(info.actors.every((a) => shown[a.name] === traces.get(a.name).leaves.at(-1)), 'at the end every box shows its actor\u2019s last states');

  // The robot shown; at positions of its timeline every other box follows the robot's time.
  await page.click('#system-svg .actor[data-name="robot"]');
  const robotPlace = info.actors.findIndex((a) => a.name === 'robot');
  check(await waitFor(page, (i) => window.bscInspector.selected === i && window.bscInspector.dictionary.chart === 'RobotActor', robotPlace, 'the robot'), 'a click shows the robot\u2019s chart');
  const robot = traces.get('robot');
  const moveTo = (i) =>
    page.$eval('#timeline', (range, value) => {
      range.value = String(value);
      range.dispatchEvent(new Event('input', { bubbles: true }));
    }, i);
  const transitions = robot.records.map((r, i) => (r.type === BscTrace.RecordType.transition ? i : -1)).filter((i) => i >= 0);
  const picks = [transitions[2], transitions[Math.floor(transitions.length / 2)], transitions.at(-3)].filter((i) => i !== undefined);
  const seen = new Set();
  for (const i of picks) {
    await moveTo(i);
    const time = robot.records[i].time;
    shown = await boxStates();
    const want = Object.fromEntries(
      info.actors.map((a) => {
        const t = traces.get(a.name);
        let k = -1;
        while (k + 1 < t.records.length && t.records[k + 1].time <= time) ++k;
        return [a.name, a.name === 'robot' ? t.leaves[i] : k >= 0 ? t.leaves[k] : ''];
      }),
    );
    const wrong = info.actors.filter((a) => shown[a.name] !== want[a.name]).map((a) => `${a.name}: '${shown[a.name]}' not '${want[a.name]}'`);
    check(wrong.length === 0, `at the robot's record ${i} (${robot.records[i].text}) every box shows its actor then${wrong.length ? `: ${wrong.join('; ')}` : ''}`);
    seen.add(JSON.stringify(want));
  }
  check(seen.size === picks.length && picks.length === 3, `the ${picks.length} positions show different moments of the cell`);
  await page.screenshot({ path: path.join(out, 'inspector_replay_system.png') });
}

// ---- Replay ---------------------------------------------------------------------------------

// The reader the page uses, loaded from the page's folder and run as the page runs it: a classic
// script that defines the global BscTrace.
function loadReader(webRoot) {
  const file = path.join(webRoot, 'trace.js');
  vm.runInThisContext(fs.readFileSync(file, 'utf8'), { filename: file });
  return globalThis.BscTrace;
}

// Every record of a trace with its describe() text, and the reader that read them.
function readTrace(BscTrace, bytes) {
  const reader = new BscTrace.TraceReader();
  reader.feed(bytes);
  const records = [];
  for (let r; (r = reader.next()); ) records.push({ ...r, text: reader.describe(r) });
  return { reader, records };
}

// The configuration after each record, as state numbers, worked out here from the records
// (not with the page's TraceState): a machine that starts enters its root, state 1, first; a
// configuration record sets the active states (begins) or adds to them.
function configurations(BscTrace, records) {
  const { RecordType } = BscTrace;
  const active = new Set();
  return records.map((r) => {
    if (r.type === RecordType.entry && r.state === 1) active.clear();
    if (r.type === RecordType.entry) active.add(r.state);
    if (r.type === RecordType.exit) active.delete(r.state);
    if (r.type === RecordType.configuration) {
      if (r.begins) active.clear();
      for (const n of r.active) active.add(n);
    }
    return [...active];
  });
}

// The lines of tools/bsc-trace, a reader of the format written apart from the page's, must be
// the page reader's describe() lines, and its counts the same.
function checkAgainstBscTrace(file, trace, python) {
  const result = spawnSync(python, [BSC_TRACE, file], { encoding: 'utf8', timeout: 20_000 });
  if (result.error || result.status !== 0) throw new Error(`${python} ${BSC_TRACE}: ${result.error?.message ?? result.stderr.trim()}`);
  const theirs = result.stdout.split('\n').filter((l) => l !== '');
  const ours = trace.records.map((r) => r.text);
  const differ = ours.findIndex((l, i) => l !== theirs[i]);
  check(
    theirs.length === ours.length && differ < 0,
    `${path.basename(file)}: the page's reader describes the ${ours.length} records as bsc-trace does` +
      (differ >= 0 ? ` (record ${differ}: '${ours[differ]}' vs '${theirs[differ]}')` : theirs.length !== ours.length ? ` (bsc-trace: ${theirs.length})` : ''),
  );
  const r = trace.reader;
  const counts = `${r.frames} frames, ${r.missing} lost, ${r.skippedBytes} bytes skipped, ${r.malformed} malformed`;
  check(result.stderr.trim() === counts, `${path.basename(file)}: and counts as it does (${counts})`);
}

// One frame of the stream (include/bsc/detail/trace/format.hpp).
function frame(BscTrace, type, sequence, payload) {
  const n = payload.length;
  const bytes = new Uint8Array(7 + n);
  bytes.set([0xb5, type, sequence & 0xff, (sequence >> 8) & 0xff, n]);
  bytes.set(payload, 5);
  const crc = BscTrace.crc16(bytes, 1, 5 + n);
  bytes.set([crc & 0xff, crc >> 8], 5 + n);
  return bytes;
}

// The stream a page sees that starts reading where a program wrote its dictionary again: the
// recorded dictionary (its frames from the start of the file), then configuration records only,
// with one malformed among them (begins 2), which both readers must skip.
function joinedLate(BscTrace, bytes, first, last) {
  let end = 0;
  let sequence = 0;
  while (end + 5 <= bytes.length && bytes[end] === 0xb5 && bytes[end + 1] >= 0x01 && bytes[end + 1] <= 0x05) {
    sequence = bytes[end + 2] | (bytes[end + 3] << 8);
    end += 7 + bytes[end + 4];
  }
  const states = (list) => list.flatMap((n) => [n & 0xff, n >> 8]);
  const half = Math.ceil(last.length / 2);
  const frames = [
    [1, first],
    [2, [1]],
    [1, last.slice(0, half)],
    [0, last.slice(half)],
  ].map(([begins, list]) => frame(BscTrace, BscTrace.RecordType.configuration, ++sequence, [begins, ...states(list)]));
  return Buffer.concat([bytes.subarray(0, end), ...frames]);
}

async function replay(page, options, out) {
  const webRoot = path.resolve(options['web-root']);
  if (!fs.existsSync(path.join(webRoot, 'elk.bundled.js'))) throw new Skip(`no elk.bundled.js in ${webRoot} (npm install in web/, then build)`);
  const BscTrace = loadReader(webRoot);
  const { RecordType, NONE } = BscTrace;
  const bytes = fs.readFileSync(options.trace);
  const cell = readTrace(BscTrace, bytes);
  const { records, reader } = cell;
  const d = reader.dictionary;
  const names = (list) => list.map((n) => d.stateName(n));
  cell.expected = configurations(BscTrace, records).map(names);
  check(records.length > 0 && reader.frames === records.length, `the trace has ${records.length} records`);
  checkAgainstBscTrace(options.trace, cell, options.python);

  await page.goto(pathToFileURL(path.join(webRoot, 'index.html')).href);
  await page.waitForSelector('#trace-file', { state: 'attached', timeout: WAIT_MS });
  check(await page.isVisible('#open'), 'the page offers to open a trace file');
  await page.setInputFiles('#trace-file', options.trace);
  check(await waitFor(page, () => window.bscInspector?.ready, null, 'the chart'), 'the page drew the chart');
  check((await page.evaluate(() => window.bscInspector.records.length)) === records.length, 'the page read every record');

  const states = await page.$$eval('g[data-state]', (gs) => gs.map((g) => g.dataset.state));
  const stateNames = d.states.filter((s) => s.kind !== 0).map((s) => s.name);
  check(sameSet(states, stateNames), `every state is drawn (${states.length})`);
  check(['Belt', 'Drill'].every((s) => states.includes(s)), 'the components Belt and Drill are drawn');
  const withTarget = d.rows.filter((row) => row.source !== NONE && row.target !== NONE).length;
  check((await page.$$eval('g.edge', (gs) => gs.length)) === withTarget, `every transition with a target is an edge (${withTarget})`);

  // Shows position i as the page has it, and compares it with the expectation.
  const atPosition = async (trace, i, how) => {
    const want = trace.expected[i];
    const shown = await page.evaluate(() => ({ position: window.bscInspector.position(), active: window.bscInspector.active() }));
    check(shown.position === i, `${how}: the timeline is at record ${i} (${shown.position})`);
    check(sameSet(shown.active, want), `${how}: the configuration is ${want.join(' ') || '(none)'}`);
    check(sameSet(await drawnActive(page), want), `${how}: the drawing marks it`);
    const lastLine = await page.$eval('#log', (log) => log.lastElementChild?.textContent ?? '');
    check(lastLine === trace.records[i].text, `${how}: the log ends at '${trace.records[i].text}'`);
  };
  const moveTo = (i) =>
    page.$eval('#timeline', (range, value) => {
      range.value = String(value);
      range.dispatchEvent(new Event('input', { bubbles: true }));
    }, i);

  const last = records.length - 1;
  await atPosition(cell, last, 'after loading');
  await page.focus('#timeline');
  await page.keyboard.press('Home');
  await atPosition(cell, 0, 'at the start');
  await page.keyboard.press('End');
  await atPosition(cell, last, 'at the end');

  // Positions where the configuration differs: after the first full configuration, right after
  // transitions, and the steps around one.
  const transitions = records.map((r, i) => (r.type === RecordType.transition ? i : -1)).filter((i) => i >= 0);
  const firstCycle = records.findIndex((r) => r.type === RecordType.cycle || r.type === RecordType.dispatch);
  const picks = [firstCycle, transitions[Math.floor(transitions.length / 2)] + 1, transitions[transitions.length - 1] - 1].filter(
    (i) => i > 0 && i <= last,
  );
  for (const i of picks) {
    await moveTo(i);
    await atPosition(cell, i, `moved to ${i}`);
  }
  let at = picks[1] ?? Math.floor(last / 2);
  await moveTo(at);
  for (let k = 1; k <= 3 && at > 0; ++k) {
    await page.click('#step-back');
    await atPosition(cell, --at, `stepped back ${k}`);
  }
  for (let k = 1; k <= 4 && at < last; ++k) {
    await page.click('#step-forward');
    await atPosition(cell, ++at, `stepped forward ${k}`);
  }
  const shownConfigurations = new Set([0, last, ...picks].map((i) => [...cell.expected[i]].sort().join(' ')));
  check(shownConfigurations.size >= 3, `the positions checked show ${shownConfigurations.size} different configurations`);

  // The members at the end, as the trace's last values give them.
  await page.click('#live');
  const values = new Map();
  for (const r of records) if (r.type === RecordType.values) for (const v of r.values) values.set(v.member, v.bits);
  const table = await page.$$eval('#members tr[data-member]', (trs) => trs.map((tr) => [tr.dataset.member, tr.querySelector('td.value').textContent]));
  const want = [...values].map(([n, bits]) => [d.memberName(n), d.valueText(n, bits)]);
  check(
    want.length > 0 && want.every(([name, text]) => table.some(([n, t]) => n === name && t === text)),
    `the members table shows the last values (${want.length} members)`,
  );
  await atPosition(cell, last, 'live again');
  await page.screenshot({ path: path.join(out, 'inspector_replay.png') });

  // A page that starts at a dictionary written again learns the configuration from the
  // configuration records after it, without a single entry.
  const numbers = configurations(BscTrace, records);
  const first = numbers[firstCycle];
  const final = numbers[last];
  check(final.length >= 2 && !sameSet(names(first), names(final)), 'the cell\'s first and last configurations differ');
  const lateFile = path.join(out, 'cell_joined_late.bsctrace');
  fs.writeFileSync(lateFile, joinedLate(BscTrace, bytes, first, final));
  const late = readTrace(BscTrace, fs.readFileSync(lateFile));
  late.expected = configurations(BscTrace, late.records).map(names);
  const lastLate = late.records.length - 1;
  check(late.reader.malformed === 1 && late.records[lastLate].type === RecordType.configuration, 'the page\'s reader skips the malformed configuration record');
  check(/^\[\d+\w*\] configuration \(more\) /.test(late.records[lastLate].text), `it describes one that goes on: '${late.records[lastLate].text}'`);
  checkAgainstBscTrace(lateFile, late, options.python);
  await page.setInputFiles('#trace-file', lateFile);
  check(
    await waitFor(page, (n) => window.bscInspector.records.length === n, late.records.length, 'the second trace'),
    `the page read the ${late.records.length} records of a trace that starts at a dictionary`,
  );
  await atPosition(late, lastLate, 'joined late');
  check(sameSet(late.expected[lastLate], names(final)), 'the configuration records give the last configuration');
  await page.click('#step-back');
  await atPosition(late, lastLate - 1, 'joined late, one back (a configuration begins)');
  await page.click('#step-back');
  await atPosition(late, lastLate - 2, 'joined late, two back (the one before it)');
  const counters = (await page.textContent('#counters')).trim();
  check(/\b1 malformed\b/.test(counters), `the page counts the malformed record ('${counters}')`);
}

// ---- Main -----------------------------------------------------------------------------------

async function main() {
  const { mode, options } = parseArgs(process.argv.slice(2));
  if (!fs.existsSync(CHROMIUM)) {
    console.log(`inspector ${mode}: skipped: ${CHROMIUM} is not installed`);
    process.exit(SKIP);
  }
  const playwrightDir = path.resolve(options['node-modules'], 'playwright-core');
  if (!fs.existsSync(path.join(playwrightDir, 'package.json'))) {
    console.log(`inspector ${mode}: skipped: no playwright-core in ${options['node-modules']} (npm install in web/)`);
    process.exit(SKIP);
  }
  const { chromium } = createRequire(import.meta.url)(playwrightDir);
  const out = path.resolve(options.out);
  fs.mkdirSync(out, { recursive: true });

  let page = null;
  const problems = [];
  let code = 0;
  try {
    browser = await chromium.launch({ executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS, timeout: 30_000 });
    page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    // A failed request is reported with its address by the response, without it by the console.
    page.on('console', (m) => m.type() === 'error' && !m.text().startsWith('Failed to load resource') && problems.push(`console: ${m.text()}`));
    // A command the program refuses (400) is an answer the test checks, not a fault of the page.
    const refused = (r) => r.status() === 400 && new URL(r.url()).pathname === '/command';
    page.on('response', (r) => r.status() >= 400 && !refused(r) && problems.push(`HTTP ${r.status()} for ${r.url()}`));
    if (mode === 'live') await live(page, options, out);
    else if (mode === 'system') await system(page, options, out);
    else if (mode === 'replay-system') await replaySystem(page, options, out);
    else await replay(page, options, out);
    check(problems.length === 0, `the page reported no error${problems.length ? `: ${problems.join('; ')}` : ''}`);
  } catch (e) {
    if (e instanceof Skip) {
      console.log(`inspector ${mode}: skipped: ${e.message}`);
      code = SKIP;
    } else {
      console.error(`inspector ${mode}: FAILED: ${e.message}`);
      for (const p of problems) console.error(`  ${p}`);
      if (page) await page.screenshot({ path: path.join(out, `inspector_${mode}_failure.png`) }).catch(() => {});
      code = 1;
    }
  } finally {
    if (browser) await Promise.race([browser.close().catch(() => {}), sleep(5000)]);
    clearTimeout(deadline);
  }
  if (code === 0) console.log(`inspector ${mode}: ${passed} checks passed`);
  process.exit(code);
}

main();
