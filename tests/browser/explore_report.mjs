// Drives headless Chromium through a written report as a reader would (tests/report/report_explore.sh):
// hovers and clicks a map cell and checks the panel against the map's runs.csv, its runs'
// charts against runs/FIGURE.js and runs.csv, the same cell marked on the other maps, follows a
// claim's link and checks the cells it marks against points.csv, times the page, takes
// screenshots at two widths. Any console error or warning, page error or request that is not
// a file of the report fails the test.
// Usage: node explore_report.mjs REPORT_DIR CHROMIUM SCREENSHOT_DIR
import fs from 'node:fs';
import path from 'node:path';
import puppeteer from 'puppeteer-core';

const [dir, chromium, shots] = process.argv.slice(2);
let failed = false;
const fail = (why) => { console.log(`FAIL: ${why}`); failed = true; };
const csv = (file) => {
  const [head, ...lines] = fs.readFileSync(path.join(dir, file), 'utf8').trim().split('\n');
  const cols = head.split(',');
  return lines.map((l) => Object.fromEntries(l.split(',').map((v, i) => [cols[i], v])));
};

const browser = await puppeteer.launch({
  executablePath: chromium, headless: true, args: ['--no-sandbox', '--disable-gpu'],
});
try {
  const page = await browser.newPage();
  page.on('console', (m) => fail(`console ${m.type()}: ${m.text()}`));
  page.on('pageerror', (e) => fail(`page error: ${e.message}`));
  page.on('requestfailed', (r) => fail(`request failed: ${r.url()}`));
  await page.setRequestInterception(true);
  page.on('request', (r) => {
    if (/^(file|data):/.test(r.url())) return r.continue();
    fail(`network request: ${r.url()}`);
    return r.abort();
  });
  await page.setViewport({ width: 1300, height: 900 });
  await page.goto(`file://${path.resolve(dir)}/index.html`, { waitUntil: 'load' });
  const ready = await page.evaluate(() => window.PNEUMACHAOS_READY);
  console.log(`usable after ${ready === undefined ? '?' : ready.toFixed(0)} ms`);
  if (!(ready < 2000)) fail('the maps were not usable within 2 s of opening');

  await checkCell(page);
  await checkJudge(page);
  await checkClaim(page);
  for (const width of [1300, 420]) await screenshot(page, width);
} finally {
  await browser.close();
}
console.log(failed ? 'explore: failed' : 'explore: ok');
process.exit(failed ? 1 : 0);

// The first map's first evaluated point with two runs: its tooltip and its panel.
async function checkCell(page) {
  const map = await page.evaluate(() => {
    const m = window.PNEUMACHAOS_REPORT.maps[0];
    return { sweep: m.sweep, repeats: m.repeats, x: m.axes[0] };
  });
  const runs = csv(`${map.sweep}/runs.csv`);
  const point = runs.find((r) => r.lambda_per_s !== 'nan').point;
  const mine = runs.filter((r) => r.point === point);
  const cell = `.cell[data-map="0"][data-point="${point}"]`;
  await page.hover(cell);
  const tip = await page.$eval('#tip', (t) => (t.hidden ? '' : t.textContent));
  if (!tip.includes(`${map.x} = ${mine[0][map.x]}`) || !tip.includes(mine[0].regime))
    fail(`tooltip of point ${point}: "${tip}"`);
  const clicked = Date.now();
  await page.click(cell);
  const rows = await page.$$eval('#panel table.runs tr[data-repeat]', (trs) => trs.map((tr) =>
    Object.fromEntries([...tr.querySelectorAll('td[data-col]')]
      .map((td) => [td.dataset.col, td.textContent]))));
  if (rows.length !== mine.length) fail(`panel lists ${rows.length} runs, runs.csv ${mine.length}`);
  mine.forEach((r, k) => {
    for (const col of ['repeat', 'seed', 'regime', 'lambda_per_s', 'lambda_uncertainty_per_s',
      'zero_one_K', 'paper_chaotic']) {
      if (!rows[k] || rows[k][col] !== r[col])
        fail(`run ${point}:${r.repeat} ${col}: panel ${rows[k] && rows[k][col]}, ` +
          `runs.csv ${r[col]}`);
    }
  });
  const commands = await page.$$eval('#panel pre.replay', (p) => p.map((e) => e.textContent));
  if (commands.length !== map.repeats || !commands[0].includes(`--replay ${point}:0`))
    fail(`replay commands: ${commands.join(' | ')}`);
  console.log(`cell ${point}: ${rows.length} runs as in runs.csv`);
  await checkCharts(page, mine, clicked);
  await checkTwins(page, point);
}

// The judge's choice: under the paper's three indices every cell's grey is its
// paper_chaos_incidence in points.csv, and back under the verdict its chaos_incidence.
async function checkJudge(page) {
  const maps = await page.evaluate(() => window.PNEUMACHAOS_REPORT.maps.map((m) => m.sweep));
  const fills = () => page.$$eval('.cell', (g) => g.map((e) =>
    [+e.dataset.map, +e.dataset.point, e.querySelector('rect').getAttribute('fill')]));
  const grey = (f) => { const v = Math.round(255 * (1 - Number(f))); return `rgb(${v},${v},${v})`; };
  const expect = async (column) => {
    let differ = 0;
    const points = maps.map((sweep) => csv(`${sweep}/points.csv`));
    for (const [k, p, fill] of await fills()) {
      const want = grey(points[k].find((q) => Number(q.point) === p)[column]);
      if (fill !== want) { fail(`map ${k} point ${p} under ${column}: ${fill}, want ${want}`); return 0; }
      differ += grey(points[k].find((q) => Number(q.point) === p).chaos_incidence) !== want;
    }
    return differ;
  };
  if (!(await page.$('#judge-paper'))) { fail('no choice of judge above the maps'); return; }
  await page.click('#judge-paper');
  const changed = await expect('paper_chaos_incidence');
  await page.click('#judge-strict');
  await expect('chaos_incidence');
  console.log(`judge: ${changed} cells shaded otherwise by the paper's indices, as points.csv`);
}

// The map's runs/FIGURE.js as the page reads it: "POINT:REPEAT" -> traces.
function traces(file) {
  const s = fs.readFileSync(path.join(dir, file), 'utf8');
  return JSON.parse(s.slice(s.indexOf('] = ') + 4, s.lastIndexOf(';')));
}
// A series' first value, decoded here independently of the page's own decoder.
function firstValue(s) {
  const a = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
  return s.lo + (s.hi - s.lo) * (a.indexOf(s.q[0]) * 64 + a.indexOf(s.q[1])) / 4095;
}

// Each run's charts: drawn within 2 s of the click, from that run's traces (point count and
// first value against the data file), and the traces from that run (the spectrum's broadband
// share and the ACF's late envelope equal the ones runs.csv holds, to the last digit).
async function checkCharts(page, mine, clicked) {
  await page.waitForSelector('#panel .run svg.chart', { timeout: 5000 }).catch(() => {});
  const ms = Date.now() - clicked;
  console.log(`run charts drawn ${ms} ms after the click`);
  if (ms > 2000) fail('the run charts took more than 2 s');
  const file = await page.evaluate(() => window.PNEUMACHAOS_REPORT.maps[0].runs_file);
  const all = traces(file);
  for (const r of mine) {
    const key = `${r.point}:${r.repeat}`, t = all[key];
    if (!t || !t.v) { fail(`${file} has no record of run ${key}`); continue; }
    const drawn = await page.$$eval(`#panel .run[data-run="${key}"] svg.chart`, (c) => c.map((e) =>
      ({ kind: e.dataset.kind, n: +e.dataset.n, first: +e.dataset.first,
         points: e.querySelector('polyline').getAttribute('points').split(' ').length })));
    const want = { v: t.v, spectrum: t.spectrum, acf: t.acf };
    for (const [kind, s] of Object.entries(want)) {
      const c = drawn.find((d) => d.kind === kind);
      if (!s) continue;
      if (!c || c.n !== s.n || c.points !== s.n || Math.abs(c.first - firstValue(s)) > 1e-12)
        fail(`run ${key} ${kind} chart ${JSON.stringify(c)}; ${file}: ${s.n} points, ` +
          `first ${firstValue(s)}`);
    }
    if (!t.spectrum || !t.acf ||
        Number(t.spectrum.broadband_share) !== Number(r.broadband_share) ||
        Number(t.acf.late_acf) !== Number(r.late_acf))
      fail(`run ${key}'s traces are not its record: ${JSON.stringify([t.spectrum, t.acf])}, ` +
        `runs.csv broadband ${r.broadband_share}, late ACF ${r.late_acf}`);
  }
  console.log(`run charts of ${mine.length} runs match ${file} and runs.csv`);
}

// The same S1, S2 on the other maps: marked when the cell is open and when one is hovered,
// and compared in the panel's table.
async function checkTwins(page, point) {
  const maps = await page.evaluate(() => window.PNEUMACHAOS_REPORT.maps.map((m) => m.cells));
  const at = (k, p) => maps[k].find((c) => c.point === p);
  const marked = (cls) => page.$$eval(`.cell.${cls}`, (g) => g.map((e) =>
    [+e.dataset.map, +e.dataset.point]));
  const expect = (got, from, p, what) => {
    const want = maps.map((m, k) => k).filter((k) => k !== from);
    if (got.map(([k]) => k).join() !== want.join() ||
        got.some(([k, q]) => at(k, q).x !== at(from, p).x || at(k, q).y !== at(from, p).y))
      fail(`${what}: marked ${JSON.stringify(got)}, want point ${p} on maps ${want}`);
  };
  expect(await marked('same'), 0, Number(point), 'the open cell elsewhere');
  const rows = await page.$$eval('#panel table.compare tr[data-map]', (r) => r.map((e) =>
    [+e.dataset.map, +e.dataset.x, +e.dataset.y]));
  const c = at(0, Number(point));
  if (rows.length !== maps.length || rows.some(([, x, y]) => x !== c.x || y !== c.y))
    fail(`the compare table: ${JSON.stringify(rows)}`);
  const other = maps[1][maps[1].length - 1].point;
  await page.hover(`.cell[data-map="1"][data-point="${other}"]`);
  expect(await marked('twin'), 1, other, 'the hovered cell elsewhere');
  console.log(`cell ${point} marked on ${maps.length - 1} other maps; hovered ${other} too`);
}

// fig4_border's link: it leads to the Fig. 4 map and marks the points within one grid step
// of the stick-slip border, recomputed here from points.csv.
async function checkClaim(page) {
  const id = 'fig4_border', figure = 'fig4_map_ps025_m15';
  await page.click(`#claim-${id} a`);
  const hash = await page.evaluate(() => location.hash);
  if (hash !== `#explore-${figure}`) fail(`the claim's link led to "${hash}"`);
  const sweep = await page.evaluate(() => window.PNEUMACHAOS_REPORT.maps[0].sweep);
  const pts = csv(`${sweep}/points.csv`);
  const n2 = new Set(pts.map((p) => p['circuit.S2_mm2'])).size, n1 = pts.length / n2;
  const ss = pts.map((p) => Number(p.stick_slip_incidence) >= 0.5);
  const border = pts.map((p, i) => i).filter((i) => {
    const a = Math.floor(i / n2), b = i % n2;
    return (b > 0 && ss[i - 1] !== ss[i]) || (b + 1 < n2 && ss[i + 1] !== ss[i]) ||
      (a > 0 && ss[i - n2] !== ss[i]) || (a + 1 < n1 && ss[i + n2] !== ss[i]);
  });
  const named = await page.$$eval(`#explore-${figure} .cell.named`,
    (g) => g.map((e) => Number(e.dataset.point)));
  if (border.length === 0 || named.join() !== border.join())
    fail(`${id} marks ${named.join()}; the border is ${border.join()}`);
  const claimed = await page.$eval(`#explore-${figure}`, (e) => e.classList.contains('claimed'));
  if (!claimed) fail(`${id}'s map is not highlighted`);
  // And back: the map lists the claim, linked to its row.
  const back = await page.$$eval(`#explore-${figure} .mapclaims a`, (a) => a.map((e) => e.hash));
  if (!back.includes(`#claim-${id}`)) fail(`the ${figure} map does not list ${id}: ${back}`);
  console.log(`claim ${id}: ${named.length} border cells marked`);
}

// A full-page screenshot at this width, written to the screenshot folder, and the share of
// its pixels that differ from the top-left one (0: a blank page).
async function screenshot(page, width) {
  await page.setViewport({ width, height: 900 });
  const b64 = await page.screenshot({ encoding: 'base64', fullPage: true });
  fs.writeFileSync(path.join(shots, `report_${width}.png`), Buffer.from(b64, 'base64'));
  const inked = await page.evaluate(async (data) => {
    const img = new Image();
    img.src = `data:image/png;base64,${data}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = Math.min(img.height, 4000);
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    let differ = 0;
    for (let i = 0; i < px.length; i += 4)
      if (px[i] !== px[0] || px[i + 1] !== px[1] || px[i + 2] !== px[2]) ++differ;
    return differ / (px.length / 4);
  }, b64);
  console.log(`screenshot ${width} px: ${(100 * inked).toFixed(1)} % of pixels inked`);
  if (!(inked > 0.02)) fail(`the ${width} px screenshot is blank`);
}
