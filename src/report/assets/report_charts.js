// The run panel's line charts (velocity record, spectrum, autocorrelation) as small SVGs, and
// the decoding of the series runs/FIGURE.js holds (src/report/run_traces.cpp quantises each
// value to 12 bits, two base64 characters). Plain SVG: a few hundred points per chart, no zoom
// (docs/notes/explorable_report.md says why no charting library is vendored).
window.PNEUMACHAOS_CHARTS = (function () {
  'use strict';
  const SVG = 'http://www.w3.org/2000/svg';
  const ALPHABET = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
  const W = 330, H = 170, L = 54, R = 10, T = 20, B = 34;

  // The values of a series: value k = lo + (hi - lo) * code / 4095.
  function decode(s) {
    const out = new Array(s.n);
    for (let k = 0; k < s.n; ++k) {
      const code = ALPHABET.indexOf(s.q[2 * k]) * 64 + ALPHABET.indexOf(s.q[2 * k + 1]);
      out[k] = s.lo + (s.hi - s.lo) * code / 4095;
    }
    return out;
  }

  function node(tag, attrs, text) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  const fmt = (v) => (Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-2)
    ? v.toExponential(1) : String(+v.toPrecision(3)));

  // A line chart of series s (x0 + k dx against its values), titled, with its axes' ends
  // labelled; marks: x positions drawn as dashed verticals (a spectrum's peak), zero: a
  // dashed horizontal at y = 0 when in range.
  function chart(kind, title, xLabel, s, marks, zero) {
    const y = decode(s);
    const x1 = s.x0 + s.dx * Math.max(s.n - 1, 1);
    const lo = s.lo, hi = s.hi > s.lo ? s.hi : s.lo + 1;
    const px = (x) => L + (W - L - R) * (x - s.x0) / (x1 - s.x0);
    const py = (v) => T + (H - T - B) * (hi - v) / (hi - lo);
    const g = node('svg', { width: W, height: H, viewBox: `0 0 ${W} ${H}`, class: 'chart',
      'data-kind': kind, 'data-n': s.n, 'data-first': y[0] });
    g.appendChild(node('text', { x: L, y: 13, class: 'title' }, title));
    g.appendChild(node('rect', { x: L, y: T, width: W - L - R, height: H - T - B, class: 'frame' }));
    (marks || []).forEach((m) => g.appendChild(node('line', { x1: px(m), x2: px(m), y1: T,
      y2: H - B, class: 'mark' })));
    if (zero && lo < 0 && hi > 0) {
      g.appendChild(node('line', { x1: L, x2: W - R, y1: py(0), y2: py(0), class: 'mark' }));
    }
    g.appendChild(node('polyline', { class: 'trace',
      points: y.map((v, k) => `${px(s.x0 + k * s.dx).toFixed(1)},${py(v).toFixed(1)}`).join(' ') }));
    const tick = (x, yy, text, anchor) => g.appendChild(node('text', { x, y: yy,
      'text-anchor': anchor, class: 'tick' }, text));
    tick(L - 3, T + 8, fmt(hi), 'end');
    tick(L - 3, H - B, fmt(lo), 'end');
    tick(L, H - B + 12, fmt(s.x0), 'start');
    tick(W - R, H - B + 12, fmt(x1), 'end');
    tick(L + (W - L - R) / 2, H - 4, xLabel, 'middle');
    return g;
  }

  // The three charts of one run's traces.
  function runCharts(t) {
    const box = document.createElement('div');
    box.className = 'charts';
    box.appendChild(chart('v', `velocity [m/s], ${t.samples} samples at ${t.rate_Hz} Hz`,
      'time [s]', t.v));
    if (t.spectrum) {
      box.appendChild(chart('spectrum', `log10 PSD, peak ${fmt(t.spectrum.peak_Hz)} Hz`,
        'frequency [Hz]', t.spectrum, [t.spectrum.peak_Hz]));
    }
    if (t.acf) box.appendChild(chart('acf', 'autocorrelation', 'lag [s]', t.acf, [], true));
    return box;
  }

  return { decode, runCharts };
})();
