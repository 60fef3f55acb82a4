// The report's explorable maps: each map of report_data.js drawn as an SVG grid; hovering a
// cell shows its incidences and marks the same cell on the other maps, clicking it lists its
// runs as runs.csv holds them with each run's record, spectrum and autocorrelation (loaded per
// map from runs/FIGURE.js on the first click: the full report's traces are megabytes) and
// compares the cell across the maps. Plain DOM and SVG, no library: the page must work from
// disk with no network (docs/notes/explorable_report.md says why no library is vendored).
(function () {
  'use strict';
  const data = window.PNEUMACHAOS_REPORT;
  const SVG = 'http://www.w3.org/2000/svg';
  const PAD = 58;
  // runs.csv columns the panel shows, with their headings; the rest stay in runs.csv.
  const RUN_COLUMNS = [
    ['repeat', 'repeat'], ['seed', 'seed'], ['regime', 'verdict'],
    ['chaotic', 'chaotic'], ['paper_chaotic', 'chaotic by the paper\'s indices'],
    ['stick_slip', 'stick-slip'],
    ['lambda_per_s', 'exponent [1/s]'], ['lambda_uncertainty_per_s', '± [1/s]'],
    ['zero_one_K', '0–1 K'], ['surrogate_rank', 'surrogate rank'],
  ];
  // The verdict's evidence lines: the indices the regime verdict reads (docs/notes/analysis.md).
  const EVIDENCE = [
    ['broadband_share', 'broadband share'], ['late_acf', 'late ACF envelope'],
    ['prediction_ratio', 'prediction-error ratio'], ['repeat_share', 'self-repetition share'],
    ['sticks', 'stick events'], ['termination', 'ended by'], ['reason', 'note'],
  ];

  function el(tag, attrs, text) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  function svg(tag, attrs) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    return e;
  }
  const pct = (f) => `${Math.round(100 * f)} %`;
  // Which judge shades the maps: the regime verdict, or the paper's three indices (a spectrum
  // without a dominant line, an autocorrelation that dies, Wolf's exponent positive) where
  // every map was judged by them too.
  const JUDGES = {
    strict: { key: 'chaos', name: 'the regime verdict' },
    paper: { key: 'paper_chaos', name: 'the paper\'s three indices' },
  };
  let judge = 'strict';
  const chaosOf = (cell) => cell[JUDGES[judge].key];
  // "chaos 50 % by the verdict, 100 % by the paper's indices" (the second where judged).
  const chaosText = (cell) => `chaos ${pct(cell.chaos)} by the verdict` +
    (cell.paper_chaos === null || cell.paper_chaos === undefined ? ''
      : `, ${pct(cell.paper_chaos)} by the paper's indices`);

  function verdicts(map, cell) {
    const i = map.columns.indexOf('regime');
    if (!cell.rows.length) return 'none run (inferred from its cell)';
    return cell.rows.map((r) => r[i]).join(', ');
  }

  function tooltipText(map, cell) {
    return `${map.axes[0]} = ${cell.x}, ${map.axes[1]} = ${cell.y}\n` +
      `runs: ${cell.runs} (${cell.failed} failed): ${verdicts(map, cell)}\n` +
      `${chaosText(cell)}; stick-slip ${pct(cell.stick_slip)}` +
      (cell.inferred ? '\ninferred by the adaptive map' : '');
  }

  function drawMap(map, index) {
    // Cells of 34 px, smaller on a large grid (the paper's 26 x 30) so two maps fit side by
    // side; the tick labels thinned to fit.
    const CELL = Math.max(12, Math.min(34, Math.floor(560 / Math.max(map.x.length, map.y.length))));
    const every = (px) => Math.ceil(px / CELL);
    const w = PAD + CELL * map.x.length + 8, h = PAD + CELL * map.y.length + 8;
    const s = svg('svg', { width: w, height: h, viewBox: `0 0 ${w} ${h}`, class: 'map' });
    map.cells.forEach((cell) => {
      const i = map.x.indexOf(cell.x), j = map.y.indexOf(cell.y);
      const g = svg('g', { class: 'cell', 'data-map': index, 'data-point': cell.point,
                           tabindex: 0 });
      g.appendChild(paint(svg('rect', {
        x: PAD + i * CELL + 1, y: 4 + (map.y.length - 1 - j) * CELL + 1,
        width: CELL - 2, height: CELL - 2,
      }), cell));
      if (cell.inferred) {
        g.appendChild(svg('circle', { cx: PAD + (i + 0.5) * CELL,
          cy: 4 + (map.y.length - 0.5 - j) * CELL, r: Math.min(3, CELL / 6), class: 'inferred' }));
      }
      s.appendChild(g);
    });
    map.x.forEach((v, i) => {
      if (i % every(30) === 0) s.appendChild(label(PAD + (i + 0.5) * CELL, h - 20, v, 'middle'));
    });
    map.y.forEach((v, j) => {
      if (j % every(12) === 0) {
        s.appendChild(label(PAD - 4, 4 + (map.y.length - 0.5 - j) * CELL + 4, v, 'end'));
      }
    });
    s.appendChild(label(PAD + CELL * map.x.length / 2, h - 4, map.axes[0], 'middle'));
    const y = label(0, 0, map.axes[1], 'middle');
    y.setAttribute('transform', `translate(12 ${4 + CELL * map.y.length / 2}) rotate(-90)`);
    s.appendChild(y);
    return s;
  }
  // A cell's square shaded by the chosen judge: white no run chaotic, black all.
  function paint(rect, cell) {
    const grey = Math.round(255 * (1 - chaosOf(cell)));
    rect.setAttribute('fill', `rgb(${grey},${grey},${grey})`);
    rect.setAttribute('class', (cell.stick_slip >= 0.5 ? 'ss' : '') +
      (chaosOf(cell) === 0 && !cell.inferred ? ' calm' : ''));
    return rect;
  }
  function repaint() {
    document.querySelectorAll('.cell').forEach((g) => {
      const map = data.maps[g.dataset.map];
      paint(g.querySelector('rect'), map.cells.find((c) => c.point === +g.dataset.point));
    });
  }
  // The judge's choice, offered only when every map was judged by both.
  function judgeChoice() {
    const box = el('fieldset', { class: 'judge' });
    box.appendChild(el('legend', {}, 'Shade chaos by'));
    Object.entries(JUDGES).forEach(([id, j]) => {
      const input = el('input', { type: 'radio', name: 'judge', id: `judge-${id}`, value: id });
      if (id === judge) input.checked = true;
      input.addEventListener('change', () => {
        judge = id;
        repaint();
      });
      const l = el('label', { for: `judge-${id}` });
      l.append(input, ` ${j.name}`);
      box.appendChild(l);
    });
    return box;
  }
  function label(x, y, text, anchor) {
    const t = svg('text', { x, y, 'text-anchor': anchor, class: 'tick' });
    t.textContent = text;
    return t;
  }

  function runTable(map, cell) {
    const col = (name) => map.columns.indexOf(name);
    const t = el('table', { class: 'runs' });
    const head = el('tr');
    RUN_COLUMNS.forEach(([, h]) => head.appendChild(el('th', {}, h)));
    head.appendChild(el('th', {}, 'evidence'));
    t.appendChild(head);
    cell.rows.forEach((r) => {
      const tr = el('tr', { 'data-repeat': r[col('repeat')] });
      RUN_COLUMNS.forEach(([name]) => tr.appendChild(el('td', { 'data-col': name },
        col(name) < 0 ? 'not run' : r[col(name)])));
      const ev = el('td', { class: 'evidence' });
      EVIDENCE.forEach(([name, h]) => {
        if (col(name) >= 0 && r[col(name)] !== '') {
          ev.appendChild(el('div', {}, `${h}: ${r[col(name)]}`));
        }
      });
      tr.appendChild(ev);
      t.appendChild(tr);
    });
    return t;
  }

  // The same S1, S2 on every map (one grid, so one point index): its incidences and verdicts
  // across supply pressure and load, each row opening that map's cell.
  function compareTable(cell, index) {
    const t = el('table', { class: 'compare' });
    t.appendChild(el('caption', {}, 'The same cell on every map'));
    const head = el('tr');
    ['map', 'chaos', 'stick-slip', 'verdicts'].forEach((h) => head.appendChild(el('th', {}, h)));
    t.appendChild(head);
    data.maps.forEach((m, k) => {
      const c = m.cells.find((q) => q.point === cell.point);
      if (!c) return;
      const tr = el('tr', { 'data-map': k, 'data-x': c.x, 'data-y': c.y });
      if (k === index) tr.className = 'current';
      const a = el('a', { href: `#explore-${m.figure}` }, m.title);
      a.addEventListener('click', () => openCell(k, cell.point));
      tr.appendChild(el('td')).appendChild(a);
      [chaosText(c), pct(c.stick_slip), verdicts(m, c)].forEach((v) =>
        tr.appendChild(el('td', {}, v)));
      t.appendChild(tr);
    });
    return t;
  }

  // Marks with `cls` the cell of `point` on every map but `index` (none: point < 0).
  function markTwins(cls, index, point) {
    document.querySelectorAll(`.cell.${cls}`).forEach((g) => g.classList.remove(cls));
    if (point < 0) return;
    document.querySelectorAll(`.cell[data-point="${point}"]`).forEach((g) => {
      if (+g.dataset.map !== index) g.classList.add(cls);
    });
  }

  // Calls then(traces) with the map's runs/FIGURE.js once loaded (null if it cannot be).
  function withTraces(map, then) {
    const all = window.PNEUMACHAOS_RUNS;
    if (all && all[map.figure]) return then(all[map.figure]);
    let s = document.querySelector(`script[data-traces="${map.figure}"]`);
    if (s && s.dataset.failed) return then(null);  // an error event is not sent twice
    if (!s) {
      s = el('script', { src: map.runs_file, 'data-traces': map.figure });
      document.head.appendChild(s);
    }
    s.addEventListener('load', () => then((window.PNEUMACHAOS_RUNS || {})[map.figure] || null));
    s.addEventListener('error', () => {
      s.dataset.failed = 'yes';
      then(null);
    });
    return undefined;
  }

  // Per run: its charts (filled when the map's traces are loaded) and the command that runs
  // it alone and writes its full record as CSV.
  function runSections(map, cell) {
    const box = el('div', { class: 'runsections' });
    for (let r = 0; r < map.repeats; ++r) {
      const key = `${cell.point}:${r}`;
      const sec = el('div', { class: 'run', 'data-run': key });
      sec.appendChild(el('h4', {}, `Run ${key}`));
      sec.appendChild(el('div', { class: 'slot' }, cell.rows.length
        ? 'loading its record…' : 'not run (inferred): the command below runs it'));
      sec.appendChild(el('p', {}, 'Its full record (every sample, as CSV) and the run again, ' +
        'alone (a scenario file it names is in figures/, beside this page):'));
      sec.appendChild(el('pre', { class: 'replay' },
        `${map.replay} --replay ${key} -o run_${cell.point}_${r}.csv`));
      box.appendChild(sec);
    }
    return box;
  }

  function fillCharts(panel, open, traces) {
    if (panel.dataset.open !== open) return;  // another cell was opened meanwhile
    panel.querySelectorAll('.run').forEach((sec) => {
      const slot = sec.querySelector('.slot');
      const t = traces && traces[sec.dataset.run];
      if (!t) {
        slot.textContent = traces ? 'no record (not run)' : 'the run traces could not be loaded';
      } else if (t.error) {
        slot.textContent = `no record: ${t.error}`;
      } else {
        slot.replaceChildren(window.PNEUMACHAOS_CHARTS.runCharts(t));
        if (t.note) slot.appendChild(el('p', {}, t.note));
      }
    });
  }

  function openCell(index, point) {
    const map = data.maps[index];
    const cell = map.cells.find((c) => c.point === point);
    const panel = document.getElementById('panel');
    panel.replaceChildren();
    panel.appendChild(el('h3', {}, `${map.title}: ${map.axes[0]} = ${cell.x}, ` +
      `${map.axes[1]} = ${cell.y} (point ${cell.point})`));
    panel.appendChild(el('p', {}, `${cell.runs} runs, ${cell.failed} failed; ` +
      `${chaosText(cell)}; stick-slip ${pct(cell.stick_slip)}` + (cell.inferred
      ? '; inferred by the adaptive map from its cell: no run of its own (a command below runs one)'
      : '') + `. All columns: ${map.sweep}/runs.csv ` +
      '(surrogate rank: the maps run no surrogate test).'));
    if (cell.rows.length) panel.appendChild(runTable(map, cell));
    panel.appendChild(compareTable(cell, index));
    panel.appendChild(runSections(map, cell));
    document.querySelectorAll('.cell.open').forEach((g) => g.classList.remove('open'));
    document.querySelector(`.cell[data-map="${index}"][data-point="${point}"]`)
      .classList.add('open');
    markTwins('same', index, point);
    panel.dataset.open = `${index}:${point}`;
    panel.hidden = false;
    if (cell.rows.length) withTraces(map, (t) => fillCharts(panel, `${index}:${point}`, t));
  }

  function bindCells(root, tip) {
    root.addEventListener('mouseover', (e) => {
      const g = e.target.closest('.cell');
      if (!g) return;
      const map = data.maps[g.dataset.map];
      tip.textContent = tooltipText(map, map.cells.find((c) => c.point === +g.dataset.point));
      tip.hidden = false;
      markTwins('twin', +g.dataset.map, +g.dataset.point);
    });
    root.addEventListener('mousemove', (e) => {
      tip.style.left = `${e.pageX + 12}px`;
      tip.style.top = `${e.pageY + 12}px`;
    });
    root.addEventListener('mouseout', (e) => {
      if (!e.target.closest('.cell')) return;
      tip.hidden = true;
      markTwins('twin', -1, -1);
    });
    const open = (e) => {
      const g = e.target.closest('.cell');
      if (g) openCell(+g.dataset.map, +g.dataset.point);
    };
    root.addEventListener('click', open);
    root.addEventListener('keydown', (e) => { if (e.key === 'Enter') open(e); });
  }

  // A claim's figure link leads to its interactive map, and a click marks the cells it read.
  function linkClaims() {
    (data.claims || []).forEach((claim) => {
      const index = data.maps.findIndex((m) => m.figure === claim.figure);
      const row = document.getElementById(`claim-${claim.id}`);
      const a = row && row.querySelector(`a[href="#${claim.figure}"]`);
      if (index < 0 || !a) return;
      a.setAttribute('href', `#explore-${claim.figure}`);
      a.addEventListener('click', () => {
        document.querySelectorAll('.named, .claimed').forEach((n) =>
          n.classList.remove('named', 'claimed'));
        document.getElementById(`explore-${claim.figure}`).classList.add('claimed');
        claim.cells.forEach((p) => {
          const g = document.querySelector(`.cell[data-map="${index}"][data-point="${p}"]`);
          if (g) g.classList.add('named');
        });
      });
    });
  }

  // Under each map, the claims read from it, their verdict and numbers (the false-positive
  // allowance among them), each linked to its row of the claims table.
  function mapClaims(map) {
    const list = el('ul', { class: 'mapclaims' });
    (data.claims || []).filter((c) => c.figure === map.figure).forEach((c) => {
      const li = el('li');
      li.appendChild(el('a', { href: `#claim-${c.id}` }, c.id));
      li.appendChild(document.createTextNode(`: ${c.verdict} (${c.ours})`));
      list.appendChild(li);
    });
    return list;
  }

  function build() {
    const root = document.getElementById('explore');
    if (!root || !data) return;
    const tip = el('div', { id: 'tip', hidden: '' });
    document.body.appendChild(tip);
    const choice = data.maps.length > 0 && data.maps.every((m) => m.paper_judged);
    if (choice) root.appendChild(judgeChoice());
    const maps = el('div', { class: 'maps' });
    data.maps.forEach((map, k) => {
      const box = el('div', { class: 'mapbox', id: `explore-${map.figure}` });
      box.appendChild(el('h3', {}, map.title));
      box.appendChild(drawMap(map, k));
      box.appendChild(mapClaims(map));
      maps.appendChild(box);
    });
    root.appendChild(maps);
    root.appendChild(el('p', { class: 'legend' },
      `Grey: share of the cell's runs judged chaotic by ${choice ? 'the judge chosen above'
        : JUDGES.strict.name} (white none, black all); red border: ` +
      'stick-slip in at least half of its runs; dashed border: evaluated, no chaos; blue dot: ' +
      'inferred by the adaptive map from its cell. Hover a cell for its runs\' verdicts (the ' +
      'same cell is marked on the other maps); click it (or Enter) for its runs, their ' +
      'records, spectra and autocorrelations, and the cell on every map.'));
    const panel = el('div', { id: 'panel', hidden: '' });
    root.appendChild(panel);
    bindCells(maps, tip);
    linkClaims();
    window.PNEUMACHAOS_READY = performance.now();
  }
  build();
})();
