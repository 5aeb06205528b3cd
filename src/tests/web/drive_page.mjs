// The live page driven as a student drives it, with real mouse and key events in
// headless Chromium: a click selects a sphere; paused, its numbers typed in the inspector
// move it (a bad one is refused in one line); Ctrl+drag throws it; F and the Shoot button
// shoot a sphere, and a shot into another is refused; ← steps back; Esc deselects; P, O,
// R; the time scale; the plots; a phone's fingers (turn, pinch, throw); the panel shows the
// scene's text measured and an invariant alarm; the presentation layout, [ ] and Esc. Each check prints a line;
// the exit status is 1 when one fails.
// Chrome's DevTools protocol over a pipe (--remote-debugging-pipe: fd 3 in, fd 4 out,
// messages ended by a NUL), since Debian 12's node 18 has no WebSocket.
// Usage: node drive_page.mjs URL_OF_INDEX_HTML PROFILE_DIR
import { spawn } from 'node:child_process';

const [page, profile] = process.argv.slice(2);
const chrome = spawn('chromium', ['--headless=new', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--remote-debugging-pipe', '--user-data-dir=' + profile, '--window-size=1280,720', 'about:blank'],
  { stdio: ['ignore', 'ignore', 'ignore', 'pipe', 'pipe'] });
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const giveUp = setTimeout(() => { console.log('the page did not answer within 120 s'); chrome.kill(); process.exit(1); }, 120000);

// ---- the protocol: numbered commands, answered by id
let nextId = 0, received = Buffer.alloc(0), session;
const waiting = new Map();
chrome.stdio[4].on('data', (chunk) => {
  received = Buffer.concat([received, chunk]);
  for (let end; (end = received.indexOf(0)) >= 0; received = received.subarray(end + 1)) {
    const message = JSON.parse(received.subarray(0, end).toString());
    if (waiting.has(message.id)) { waiting.get(message.id)(message); waiting.delete(message.id); }
  }
});
const send = (method, params = {}) => new Promise((resolve, reject) => {
  const id = ++nextId;
  waiting.set(id, (m) => (m.error ? reject(new Error(method + ': ' + m.error.message)) : resolve(m.result)));
  chrome.stdio[3].write(JSON.stringify({ id, method, params, sessionId: session }) + '\0');
});
const js = async (expression) => {
  const answer = await send('Runtime.evaluate', { expression, returnByValue: true });
  if (answer.exceptionDetails) throw new Error(expression + ': ' + answer.exceptionDetails.text);
  return answer.result.value;
};
// The run's state as the page exports it ({} until the page has one).
const state = async () => {
  const exported = await js("(() => { const e = document.getElementById('state'); return e ? e.textContent : ''; })()");
  try { return JSON.parse(exported || '{}'); } catch { return {}; }
};
const text = (id) => js(`document.getElementById('${id}').textContent`);
const mouse = (type, x, y, extra = {}) => send('Input.dispatchMouseEvent', { type, x, y, button: 'left', ...extra });
const click = async (x, y) => {
  await mouse('mousePressed', x, y, { buttons: 1, clickCount: 1 });
  await mouse('mouseReleased', x, y, { clickCount: 1 });
};
const key = async (key, code, keyCode, modifiers = 0) => {
  await send('Input.dispatchKeyEvent', { type: 'rawKeyDown', key, code, windowsVirtualKeyCode: keyCode, modifiers });
  await send('Input.dispatchKeyEvent', { type: 'keyUp', key, code, windowsVirtualKeyCode: keyCode, modifiers });
};
// Waits until `test` of the page's state holds (at most `ms`): the frames run on their own clock.
const until = async (test, ms = 5000) => {
  for (const start = Date.now(); Date.now() - start < ms; await sleep(50)) {
    const now = await state();
    if (test(now)) return now;
  }
  return state();
};

// Runs `leave` (a function returning a promise) and waits until it has replaced the page's
// document by a new one, loaded: until then `state` could read the old one's.
const newDocument = async (leave) => {
  await js('window.leaving = true');
  await leave();
  for (const start = Date.now(); Date.now() - start < 30000; await sleep(50)) {
    try {
      if (await js("window.leaving === undefined && document.readyState === 'complete'")) return;
    } catch { /* between the documents */ }
  }
};
const navigate = (query) => newDocument(() => send('Page.navigate', { url: page + '?' + query }));

let failed = false;
const check = (what, ok, detail) => {
  console.log((ok ? 'ok: ' : 'FAILED: ') + what + (detail ? ' (' + detail + ')' : ''));
  if (!ok) failed = true;
};

try {
  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  ({ sessionId: session } = await send('Target.attachToTarget', { targetId, flatten: true }));
  await navigate('scene=10_pyramid');
  let run = await until((s) => s.time_s > 0.2, 30000);
  check('the pyramid runs', run.time_s > 0.2, 't = ' + run.time_s);

  // A sphere's point on the screen, from a share `top` of the canvas's height down: the
  // canvas's points asked, in the page, which sphere is there (spheres_pick, the page's own
  // click); none stays selected. [x, y, its number] in the canvas's pixels, or null.
  const canvas = await js("(() => { const b = document.getElementById('view').getBoundingClientRect(); return [b.left, b.top, b.width, b.height]; })()");
  const findSphere = (top) => js(`(() => {
    const [w, h] = [${canvas[2]}, ${canvas[3]}];
    for (let y = h * ${top}; y < h * 0.9; y += 12) for (let x = w * 0.3; x < w * 0.7; x += 12) {
      const hit = JSON.parse(call('spheres_pick', 'string', ['number', 'number', 'number', 'number'], [x, y, w, h])).selected;
      if (hit >= 0) { call('spheres_select', 'string', ['number'], [-1]); return [x, y, hit]; }
    }
    return null; })()`);
  const target = await findSphere(0.3);
  check('a sphere is in the view', target !== null);
  const [x, y] = [canvas[0] + target[0], canvas[1] + target[1]];

  // A click selects it: the inspector shows its numbers.
  await click(x, y);
  run = await until((s) => s.selected && s.selected.index === target[2]);
  check('a click selects sphere #' + target[2], run.selected && run.selected.index === target[2],
        'selected ' + JSON.stringify(run.selected && run.selected.index));
  check('its inspector is shown', !(await js("document.getElementById('inspector').hidden")) &&
        (await text('inspected')) === 'Sphere #' + target[2]);

  // Paused, its numbers are fields: a new height typed with Enter moves it in the run; a
  // radius the box cannot hold is refused in one line, and the sphere keeps its own.
  await key('p', 'KeyP', 80);
  run = await until((s) => s.paused);
  const fieldsShown = !(await js("document.getElementById('sphere-fields').hidden"));
  check('P pauses, and its numbers are fields', run.paused && fieldsShown);
  const type = async (name, value) => {
    await js(`(() => { const f = document.getElementById('sphere-fields').elements['${name}']; f.focus(); f.select(); })()`);
    await send('Input.insertText', { text: value });
    await key('Enter', 'Enter', 13);
  };
  // Enter on the fields left as they are shown edits nothing (it said "sphere #N edited"), as
  // the desktop's: the sphere keeps every digit, and the text's claims go on.
  const asShown = run.selected.p;
  await js(`(() => { const f = document.getElementById('sphere-fields').elements['pz']; f.focus(); })()`);
  await key('Enter', 'Enter', 13);
  await sleep(300);
  run = await state();
  const saidAfterEnter = await text('said');
  check('Enter on the fields as shown edits nothing', !saidAfterEnter.includes('edited') &&
        JSON.stringify(run.selected.p) === JSON.stringify(asShown) && run.claims.watched > 0 && !run.claims.interrupted,
        JSON.stringify({ said: saidAfterEnter, p: run.selected.p, claims: run.claims.interrupted }));
  await type('pz', '0.9');
  run = await until((s) => Math.abs(s.selected.p[2] - 0.9) < 1e-12);
  check('p z typed 0.9 moves it', Math.abs(run.selected.p[2] - 0.9) < 1e-12, 'p = ' + JSON.stringify(run.selected.p));
  const radius = run.selected.r;
  await type('r', '9');
  await sleep(200);
  const refused = await text('refusal');
  run = await state();
  check('r = 9 m is refused in one line', refused.length > 0 && !refused.includes('\n') && run.selected.r === radius, refused);
  const under = await js("document.getElementById('refusal').previousElementSibling.id");
  check('and said under the inspector\'s fields', under === 'sphere-fields', under);

  // Esc backs out one level at a time: out of the field, then the selection.
  await key('Escape', 'Escape', 27);
  await sleep(200);
  run = await state();
  check('Esc leaves the field first', run.selected && !(await js("document.activeElement.closest('#sphere-fields') !== null")));
  await key('Escape', 'Escape', 27);
  run = await until((s) => !s.selected);
  check('then Esc deselects', !run.selected);

  // Ctrl+drag (still paused, so that the sphere found stays where it is): the sphere follows
  // the mouse and is thrown at the mouse's speed.
  const grab = await findSphere(0.2);
  const [gx, gy] = [canvas[0] + grab[0], canvas[1] + grab[1]];
  const ctrl = 2;  // the protocol's modifier bit for Ctrl
  await mouse('mousePressed', gx, gy, { buttons: 1, clickCount: 1, modifiers: ctrl });
  for (let k = 1; k <= 8; ++k) {
    await sleep(16);
    await mouse('mouseMoved', gx + 12 * k, gy - 6 * k, { buttons: 1, modifiers: ctrl });
  }
  await mouse('mouseReleased', gx + 96, gy - 48, { clickCount: 1, modifiers: ctrl });
  const thrown = await text('said');
  const speed = Number((thrown.match(/thrown at ([0-9.]+) m\/s/) || [])[1]);
  check('Ctrl+drag throws sphere #' + grab[2], thrown.startsWith('sphere #' + grab[2] + ' thrown at') && speed > 0.1, thrown);
  run = await state();
  check('the thrown sphere is selected', run.selected && run.selected.index === grab[2]);

  // Shooting: the button along the view, and F through the mouse pointer, each add a
  // sphere; paused, a second shot through the pointer would overlap the first and is
  // refused in one line.
  const before = (await state()).spheres;
  await js("document.getElementById('shoot').click()");
  run = await until((s) => s.spheres === before + 1);
  const along = await text('said');
  check('the Shoot button shoots along the view', run.spheres === before + 1 && along.startsWith('shot sphere #' + before), along);
  await mouse('mouseMoved', canvas[0] + canvas[2] * 0.3, canvas[1] + canvas[3] * 0.3);
  await key('f', 'KeyF', 70);
  run = await until((s) => s.spheres === before + 2);
  const shot = await text('said');
  check('F shoots a sphere through the pointer', run.spheres === before + 2 && shot.startsWith('shot sphere #' + (before + 1)), shot);
  await key('f', 'KeyF', 70);
  await sleep(200);
  const second = await text('refusal');
  run = await state();
  check('a shot into the last one is refused in one line',
        run.spheres === before + 2 && second.startsWith('cannot shoot:') && !second.includes('\n'), second);

  // ← steps back one kept frame (the shots were kept).
  const cursor = run.timeline.cursor;
  await key('ArrowLeft', 'ArrowLeft', 37);
  run = await until((s) => s.timeline.cursor === cursor - 1);
  check('← steps back a frame', run.timeline.cursor === cursor - 1 && run.paused,
        'cursor ' + cursor + ' -> ' + run.timeline.cursor);

  // R restarts: the shots are gone, the time is back at the start.
  await key('r', 'KeyR', 82);
  run = await until((s) => s.spheres === before);
  check('R restarts the scene', run.spheres === before && run.time_s < 0.5, run.spheres + ' spheres, t = ' + run.time_s);

  // O (and Step) runs one time step h, paused; the time scale slows the run down; the
  // plots, unfolded, draw every readout against time.
  const h = JSON.parse(await js("call('spheres_parameters', 'string', [], [])")).find((p) => p.name === 'h').value;
  const t0 = (await state()).time_s;
  await key('o', 'KeyO', 79);
  run = await until((s) => s.time_s > t0);
  check('O runs one time step h and pauses', Math.abs(run.time_s - t0 - h) < 1e-9 && run.paused, 't ' + t0 + ' -> ' + run.time_s);
  await js(`(() => { const s = document.getElementById('time-scale'); s.value = 1000 * Math.log(0.25 / 0.01) / Math.log(4 / 0.01);
                     s.dispatchEvent(new Event('input')); })()`);
  run = await until((s) => s.time_scale !== 1);
  check('the time scale slider slows the run to 0.25 x', run.time_scale === 0.25 && (await text('time-scale-shown')) === '0.25 x',
        run.time_scale + ', shown ' + (await text('time-scale-shown')));
  // A value typed beside a slider: ε 0-10 m/s on a slider cannot reach a text's "0.01".
  const epsilon = () => js("JSON.parse(call('spheres_parameters', 'string', [], [])).find((p) => p.name === 'epsilon').value");
  await js(`(() => { const f = document.querySelector('#controls label[data-name=epsilon] input.typed');
                     f.value = '0.01'; f.dispatchEvent(new Event('change')); })()`);
  check('ε typed beside its slider: 0.01', Math.abs((await epsilon()) - 0.01) < 1e-12, 'ε = ' + (await epsilon()));
  await js(`(() => { const f = document.querySelector('#controls label[data-name=epsilon] input.typed');
                     f.value = 'abc'; f.dispatchEvent(new Event('change')); })()`);
  const notANumber = await text('refusal');
  check('ε typed abc: refused in one line, ε kept', notANumber === 'epsilon = abc: not a number' &&
        Math.abs((await epsilon()) - 0.01) < 1e-12, notANumber);
  await key('p', 'KeyP', 80);
  await js("document.getElementById('plots').open = true");
  await until((s) => s.time_s > t0 + 0.2);
  await sleep(300);
  const plots = await js("[...document.getElementById('plot-list').children].map((e) => e.tagName + ':' + e.textContent)");
  check('the plots: seven readouts against time', plots.length === 14 && plots[0].startsWith('DIV:kinetic energy (J): ') &&
        plots.filter((e) => e.startsWith('CANVAS')).length === 7, plots.filter((e) => e.startsWith('DIV')).join('; '));

  // A phone's fingers: one turns the view, two pinch it closer, and with "Drag throws
  // spheres" ticked one finger on a sphere throws it.
  await send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 2 });
  const touch = (type, points) => send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
  const [cx, cy] = [canvas[0] + canvas[2] / 2, canvas[1] + canvas[3] / 2];
  let camera = (await state()).camera;
  await touch('touchStart', [[cx, cy]]);
  for (let k = 1; k <= 5; ++k) await touch('touchMove', [[cx + 20 * k, cy]]);
  await touch('touchEnd', []);
  let turned = (await state()).camera;
  check('one finger turns the view', turned.azimuth_rad !== camera.azimuth_rad && turned.distance_m === camera.distance_m,
        JSON.stringify([camera, turned]));
  await touch('touchStart', [[cx - 40, cy], [cx + 40, cy]]);
  for (let k = 1; k <= 5; ++k) await touch('touchMove', [[cx - 40 - 20 * k, cy], [cx + 40 + 20 * k, cy]]);
  await touch('touchEnd', []);
  camera = (await state()).camera;
  check('two fingers spread: closer', camera.distance_m < 0.9 * turned.distance_m, turned.distance_m + ' -> ' + camera.distance_m);
  await js("document.getElementById('grab').checked = true");
  if (!(await state()).paused) await key('p', 'KeyP', 80);  // paused: the sphere found stays where it is
  await until((s) => s.paused);
  const fingered = await findSphere(0.2);
  const [fx, fy] = [canvas[0] + fingered[0], canvas[1] + fingered[1]];
  await touch('touchStart', [[fx, fy]]);
  for (let k = 1; k <= 6; ++k) { await sleep(16); await touch('touchMove', [[fx + 10 * k, fy - 10 * k]]); }
  await touch('touchEnd', []);
  const flung = await text('said');
  check('ticked, a finger throws sphere #' + fingered[2], flung.startsWith('sphere #' + fingered[2] + ' thrown at'), flung);
  await js("document.getElementById('grab').checked = false");
  await send('Emulation.setTouchEmulationEnabled', { enabled: false });

  // What the panel tells beside the view, as the desktop's: the scene's text measured (the
  // cradle's 16 claims at its own settings, none failed, the last at 1.6 s), and an invariant
  // alarm, lit, with why under it (the velocity-based bounce at beta = 1 gains energy at its
  // first bounce, t = 0.55 s).
  await navigate('scene=08_newtons_cradle');
  run = await until((s) => s.claims && s.claims.lines.length === 16, 30000);
  const claims = await text('claims-count');
  check('the cradle\'s text, measured: 16 claims held', claims === 'The text, measured: 16 ✓ 0 ✗ of 16' &&
        !(await js("document.getElementById('claims').hidden")), claims);
  await navigate('scene=02_bounce_projection&method=velocity&beta=1');
  run = await until((s) => s.alarms && s.alarms.length > 0, 30000);
  const alarm = await js("(() => { const a = document.querySelector('#alarms .lit'); return a ? [...a.children].map((line) => line.textContent) : null; })()");
  check('energy created: an alarm, lit, with why', alarm !== null && alarm[0].startsWith('ENERGY CREATED') &&
        alarm[1].startsWith('velocity-based bounce'), JSON.stringify(alarm));

  // The presentation layout (a link's &present): large type, the scene's text and only the
  // sliders it names; ] opens the next preset in it; Esc leaves it.
  await navigate('scene=09_column&present');
  await until((s) => s.time_s > 0, 30000);
  const shown = () => js(`(() => ({ present: document.documentElement.classList.contains('present'),
    sliders: [...document.querySelectorAll('#controls label')].filter((l) => l.offsetParent).map((l) => l.dataset.named),
    tools: document.getElementById('tools').offsetParent !== null, title: document.getElementById('title').textContent }))()`);
  let layout = await shown();
  check('&present: only the sliders the text names, no tools', layout.present && layout.sliders.length > 0 &&
        layout.sliders.every((named) => named === 'true') && !layout.tools, JSON.stringify(layout));
  await newDocument(() => key(']', 'BracketRight', 221));
  await until((s) => s.time_s > 0, 30000);  // the title is the running scene's
  layout = await shown();
  check('] opens the next preset, still presented', layout.present && layout.title.startsWith('A pyramid'), JSON.stringify(layout));
  await key('Escape', 'Escape', 27);
  await sleep(200);
  layout = await shown();
  check('Esc leaves the presentation layout: every control', !layout.present && layout.tools &&
        layout.sliders.includes('false'), JSON.stringify({ ...layout, sliders: layout.sliders.length }));
  // [ as keyboards type it with AltGr (Ctrl+Alt on Windows); Ctrl+[ alone is no key of ours.
  await js('window.leaving = true');  // a new document would lose it
  await key('[', 'BracketLeft', 219, 2);
  await sleep(500);
  const stayed = await js('window.leaving === true');
  check('Ctrl+[ opens nothing', stayed, stayed ? 'the same document' : 'a new document');
  await newDocument(() => key('[', 'Digit8', 56, 3));
  await until((s) => s.time_s > 0, 30000);
  layout = await shown();
  check('[ typed with AltGr (Ctrl+Alt) opens the previous preset', layout.title.startsWith('A column'), layout.title);
  // Side by side with its field emptied, Enter: what to write, and the views stay.
  await navigate('scene=08_newtons_cradle&compare=order=reversed');
  await until((s) => s.time_s > 0, 30000);
  await js("(() => { const f = document.getElementById('overrides'); f.value = ''; f.dispatchEvent(new KeyboardEvent('keydown', { key: 'Enter' })); })()");
  const emptied = await js("({ refusal: document.getElementById('refusal').textContent, said: document.getElementById('compare-said').textContent, views: document.getElementById('labels').children.length })");
  check('an emptied side-by-side field says what to write, the views stay', emptied.refusal.startsWith('Cannot compare: give at least one') &&
        emptied.said === '' && emptied.views === 2, JSON.stringify(emptied));
  const marks = await js("({ shown: !document.getElementById('marks-help').hidden, text: document.getElementById('marks-text').textContent })");
  check('side by side, the page says what the labels\' marks mean', marks.shown && marks.text.startsWith("Smith et al.'s five properties") &&
        marks.text.includes('positivity'), JSON.stringify(marks).slice(0, 120));
  // A click in view B selects the sphere as view B runs it, and the inspector says which view
  // (the page had always shown view A's).
  const inB = await js(`(() => {
    const b = document.getElementById('view').getBoundingClientRect();
    for (let y = b.height * 0.2; y < b.height * 0.9; y += 8) for (let x = b.width * 0.55; x < b.width * 0.95; x += 8) {
      const hit = JSON.parse(call('spheres_pick', 'string', ['number', 'number', 'number', 'number'], [x, y, b.width, b.height])).selected;
      if (hit >= 0) { call('spheres_select', 'string', ['number'], [-1]); return [b.left + x, b.top + y, hit]; }
    }
    return null; })()`);
  check('a sphere is in view B', inB !== null);
  if (inB) {
    await click(inB[0], inB[1]);
    const picked = (await until((s) => s.selected && s.selected.index === inB[2])).selected;
    const title = await text('inspected');
    check('a click in view B selects its sphere there, and the inspector says so', picked && picked.view === 'B' &&
          title === 'Sphere #' + inB[2] + ' in view B', JSON.stringify(picked && picked.view) + ', ' + title);
  }
  // R with the pair order's list focused (its name clicked) restarts and changes no setting:
  // the list's type-ahead had picked "reversed".
  const order = () => js("JSON.parse(call('spheres_parameters', 'string', [], [])).find((p) => p.name === 'order').value");
  const orderBefore = await order();
  await js("document.querySelector('#controls label[data-name=order] select').focus()");
  await send('Input.dispatchKeyEvent', { type: 'keyDown', key: 'r', code: 'KeyR', windowsVirtualKeyCode: 82, text: 'r' });  // typed: a list's type-ahead reads it
  await send('Input.dispatchKeyEvent', { type: 'keyUp', key: 'r', code: 'KeyR', windowsVirtualKeyCode: 82 });
  await sleep(300);
  check('R with the pair order\'s list focused changes no setting', (await order()) === orderBefore &&
        (await js("document.activeElement.tagName")) === 'SELECT', 'order ' + orderBefore + ' -> ' + (await order()));
  // A refused value is said under its own field, in sight (K = 0 was said 166 px above the view of the panel).
  await js(`(() => { const f = document.querySelector('#controls label[data-name=passes] input.typed');
                     f.scrollIntoView(); f.value = '0'; f.dispatchEvent(new Event('change')); })()`);
  const refusedK = await js(`(() => { const r = document.getElementById('refusal'), box = r.getBoundingClientRect();
    return { text: r.textContent, under: r.previousElementSibling && r.previousElementSibling.dataset.name,
             inSight: box.top >= 0 && box.bottom <= innerHeight }; })()`);
  check('K = 0 typed: refused under its field, in sight', refusedK.text.startsWith('passes = 0') && refusedK.under === 'passes' &&
        refusedK.inSight, JSON.stringify(refusedK));
  // h typed as the texts write it.
  await js(`(() => { const f = document.querySelector('#controls label[data-name=h] input.typed');
                     f.value = '1/240'; f.dispatchEvent(new Event('change')); })()`);
  const h240 = await js("JSON.parse(call('spheres_parameters', 'string', [], [])).find((p) => p.name === 'h').value");
  check('h typed 1/240 is 1/240 s', Math.abs(h240 - 1 / 240) < 1e-15 && (await text('refusal')) === '', 'h = ' + h240);
  // Slide 14's column side by side: every other view sets K and shock, so their sliders say they move view A only.
  await navigate('scene=21_shock_column&present');
  await until((s) => s.time_s > 0, 30000);
  const onlyA = await js("[...document.querySelectorAll('#controls label.only-a')].filter((l) => l.offsetParent).map((l) => l.dataset.name)");
  check('presented side by side, K and shock say they move view A only', JSON.stringify(onlyA) === '["passes","shock"]', JSON.stringify(onlyA));
  // Its text is longer than its box: Page Down moves it on by the box's height less a line
  // (a presenter's remote), Page Up back.
  const scrolled = () => js(`(() => { const t = document.getElementById('text');
    return { top: t.scrollTop, height: t.clientHeight, end: t.scrollHeight - t.clientHeight }; })()`);
  const unpaged = await scrolled();
  const unpagedState = await text('present-state');
  const box = await js(`(() => { const t = document.getElementById('text');
    return { height: t.clientHeight, line: parseFloat(getComputedStyle(t).lineHeight) }; })()`);
  const lines = box.height / box.line;  // within half a pixel of whole lines (a cut line was about a pixel)
  check('the presented text\'s box holds whole lines (no part of a line at its foot)',
        Math.abs(lines - Math.round(lines)) * box.line <= 0.5, JSON.stringify(box));
  await key('PageDown', 'PageDown', 34);
  await sleep(300);
  const paged = await scrolled();
  await key('PageUp', 'PageUp', 33);
  await sleep(300);
  const back = await scrolled();
  check('Page Down moves the presented text on (a page, or to its end), Page Up back', unpaged.end > 1 &&
        unpaged.top === 0 && paged.top >= Math.min(unpaged.height / 2, unpaged.end - 1) && back.top === 0,
        JSON.stringify({ unpaged, paged, back }));
  // Presented, the rain's count grows on a line of its own (its text says "nearly 200 after
  // 10 s", and the readouts are hidden), as the desktop's; the column emits nothing and has none.
  await navigate('scene=12_rain&present');
  const rain = await until((s) => s.spheres > 1, 30000);
  const rainState = await text('present-state');
  const count = rainState.match(/\n(\d+)\u00a0spheres\b/);  // the page may have emitted more since
  check('presented, the rain shows its sphere count', count !== null && Number(count[1]) >= rain.spheres,
        JSON.stringify(rainState) + ', ' + rain.spheres + ' in its state');
  check('and a scene that emits nothing shows none', !unpagedState.includes('spheres'), JSON.stringify(unpagedState));
  // Four views on a narrow page (800 x 1000: four columns were 100 px wide) or a laptop's
  // (1280 x 720) go in two rows of two, each label over its quarter; on a wide and low page
  // (1600 x 600) in one row again.
  await navigate('scene=16_bernoulli');
  const opened = await until((s) => s.spheres === 3, 30000);
  check('16 opens paused at its start, in slow motion', opened.paused === true && opened.time_s === 0 &&
        (await text('time-scale-shown')) === '0.25 x', JSON.stringify(opened));
  await sleep(300);  // a frame draws the state
  const note = await js("({ shown: !document.getElementById('paused-note').hidden, text: document.getElementById('paused-note').textContent })");
  check('paused, the view says so and how to go on', note.shown && note.text === 'Paused at t = 0.000 s: Run (P), Step (O)', JSON.stringify(note));
  const legend = await text('colour-legend');
  check('the colouring says what its colours mean', legend.startsWith('blue free, orange a bounce'), legend);
  await navigate('scene=16_bernoulli&present');
  await until((s) => s.spheres === 3, 30000);
  await sleep(300);  // a frame draws the state
  const presented = await text('present-state');
  check('presented, the page says the run is paused, in slow motion', presented === 't = 0.000 s, paused (P runs, O steps), slow motion 0.25×',
        presented);
  const rows = async (width, height) => {
    await send('Emulation.setDeviceMetricsOverride', { width, height, deviceScaleFactor: 1, mobile: false });
    await sleep(1500);
    return js("(() => { const l = document.getElementById('labels'); const s = document.getElementById('stage').getBoundingClientRect(); " +
              "return { two: l.classList.contains('two-rows'), dTop: l.children[3].getBoundingClientRect().top - s.top, half: s.height / 2 }; })()");
  };
  const narrow = await rows(800, 1000);
  check('four views on a narrow page go in two rows, D\'s label in the lower half', narrow.two && narrow.dTop >= narrow.half - 4, JSON.stringify(narrow));
  const laptop = await rows(1280, 720);
  check('and on a laptop\'s page', laptop.two && laptop.dTop >= laptop.half - 4, JSON.stringify(laptop));
  const wide = await rows(1600, 600);
  check('and in one row on a wide and low one', !wide.two && wide.dTop < 4, JSON.stringify(wide));
  await send('Emulation.clearDeviceMetricsOverride');
  // Presented, 07's text asks the class to click a sphere: the line its |v| takes is kept,
  // saying how, so that selecting one moves no slider (it moved them up a line).
  await navigate('scene=07_inclined_plane&present');
  await until((s) => s.time_s > 0, 30000);
  await sleep(300);
  const sliderTop = () => js("document.querySelector('#controls label[data-named=true]').getBoundingClientRect().top");
  const unselected = { top: await sliderTop(), state: await text('present-state') };
  await js("call('spheres_select', 'string', ['number'], [0])");
  await until((s) => s.selected && s.selected.index === 0);
  await sleep(300);  // a frame draws the state
  const selected = { top: await sliderTop(), state: await text('present-state') };
  check('presented, 07 says what a click shows, and a selected sphere moves no slider',
        unselected.state.includes('click a sphere: its |v| shows here') && selected.state.includes('sphere #0: |v|') &&
        Math.abs(selected.top - unselected.top) < 0.5, JSON.stringify({ unselected, selected }));
} catch (error) {
  check('the page answers', false, String(error));
}
clearTimeout(giveUp);
const closed = new Promise((resolve) => chrome.on('exit', resolve));
chrome.kill();
await closed;  // its profile is then free to remove
process.exit(failed ? 1 : 0);
