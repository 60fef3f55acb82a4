// Drives headless Chromium through a written report as a reader would (tests/report_explore.sh):
// hovers and clicks a map cell and checks the panel against the map's runs.csv, follows a
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
  await page.click(cell);
  const rows = await page.$$eval('#panel table.runs tr[data-repeat]', (trs) => trs.map((tr) =>
    Object.fromEntries([...tr.querySelectorAll('td[data-col]')]
      .map((td) => [td.dataset.col, td.textContent]))));
  if (rows.length !== mine.length) fail(`panel lists ${rows.length} runs, runs.csv ${mine.length}`);
  mine.forEach((r, k) => {
    for (const col of ['repeat', 'seed', 'regime', 'lambda_per_s', 'lambda_uncertainty_per_s',
      'zero_one_K']) {
      if (!rows[k] || rows[k][col] !== r[col])
        fail(`run ${point}:${r.repeat} ${col}: panel ${rows[k] && rows[k][col]}, ` +
          `runs.csv ${r[col]}`);
    }
  });
  const commands = await page.$$eval('#panel pre.replay', (p) => p.map((e) => e.textContent));
  if (commands.length !== map.repeats || !commands[0].includes(`--replay ${point}:0`))
    fail(`replay commands: ${commands.join(' | ')}`);
  console.log(`cell ${point}: ${rows.length} runs as in runs.csv`);
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
