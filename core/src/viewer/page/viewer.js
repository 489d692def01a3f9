// SwarmNet run viewer: draws a run from the data `swarmnet view` packed into this page
// (core/src/viewer/view_data.hpp describes it). Modes, chosen by the URL fragment:
//   #t=S                      interactive, starting at S seconds
//   #still&t=S&w=W&h=H        one frame of W x H pixels drawn at once (screenshots, tests)
//   #frames&from=S&fps=N&first=K&count=M&w=W&h=H
//                             frames K .. K+M-1 at times S + k/N drawn in turn, each put as a PNG
//                             data URL on a line of <pre id="out"> (`swarmnet view --video/--png`)
//   #bench&n=N&w=W&h=H        opening time and drawing time of N frames, as JSON in <pre id="out">
// Common options: label=0 leaves out the time label; links=1 draws the pairs within the nominal
// range (meta.link_range_m, or range=M metres), green where a message hopped in the last second.
// Interactive only: play=1 starts playing at once.
// In every mode <div id="status"> ends as "ok", or "error: ..." with the message also shown.
'use strict';
(function () {
  const status = document.getElementById('status');
  function fail(text) {
    status.textContent = 'error: ' + text;
    const box = document.getElementById('message');
    box.hidden = false;
    box.textContent = 'The viewer could not draw this run:\n' + text;
  }
  window.addEventListener('error', (e) => fail(e.message || String(e)));

  const params = new URLSearchParams(location.hash.slice(1));
  const mode = params.has('frames') ? 'frames' : params.has('still') ? 'still'
    : params.has('bench') ? 'bench' : 'live';
  const num = (key, fallback) => (params.has(key) ? Number(params.get(key)) : fallback);

  // ---- data -------------------------------------------------------------------------------
  function decodeBase64(text) {
    const table = new Uint8Array(128);
    const chars = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
    for (let i = 0; i < 64; i++) table[chars.charCodeAt(i)] = i;
    let n = text.length;
    while (n > 0 && (text.charCodeAt(n - 1) === 61 || text.charCodeAt(n - 1) <= 32)) n--;
    const out = new Uint8Array(Math.floor((n * 3) / 4));
    let o = 0;
    let acc = 0;
    let bits = 0;
    for (let i = 0; i < n; i++) {
      const c = text.charCodeAt(i);
      if (c <= 32) continue;
      acc = (acc << 6) | table[c];
      bits += 6;
      if (bits >= 8) {
        bits -= 8;
        out[o++] = (acc >> bits) & 255;
      }
    }
    return o === out.length ? out : out.slice(0, o);
  }

  const meta = JSON.parse(document.getElementById('meta').textContent);
  const bytes = decodeBase64(document.getElementById('blob').textContent);
  const A = {};
  for (const [name, [offset, count, type]] of Object.entries(meta.arrays)) {
    A[name] = new window[type + 'Array'](bytes.buffer, offset, count);
  }
  const N = meta.robots;
  const F = meta.frames;
  const AW = meta.arena.width_m;
  const AH = meta.arena.height_m;
  const duration = meta.duration_s;
  const states = meta.states;
  const palette = ['#1f6fb4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2',
    '#17becf', '#bcbd22', '#7f7f7f', '#393b79', '#637939'];
  const colour = (i) => palette[i % palette.length];
  const evCount = A.ev_t ? A.ev_t.length : 0;
  const objCount = A.obj_t ? A.obj_t.length : 0;

  // First index with array[i] > t (arrays in time order).
  function upper(array, t) {
    let lo = 0;
    let hi = array.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (array[mid] <= t) lo = mid + 1; else hi = mid;
    }
    return lo;
  }

  // Robot positions at time t (linear between frames), metres.
  const px = new Float32Array(N);
  const py = new Float32Array(N);
  let frameA = 0;
  function positionsAt(t) {
    const f = Math.max(0, Math.min(F - 1, t / meta.frame_s));
    const f0 = Math.floor(f);
    const f1 = Math.min(F - 1, f0 + 1);
    const a = f - f0;
    const p = A.pos;
    const sx = AW / 65535;
    const sy = AH / 65535;
    for (let r = 0; r < N; r++) {
      const i0 = (f0 * N + r) * 2;
      const i1 = (f1 * N + r) * 2;
      px[r] = (p[i0] + (p[i1] - p[i0]) * a) * sx;
      py[r] = (p[i0 + 1] + (p[i1 + 1] - p[i0 + 1]) * a) * sy;
    }
    frameA = Math.min(F - 1, Math.round(f));
  }

  // ---- view transform: screen = (ox + x * s, oy + (AH - y) * s) -------------------------
  const canvas = document.getElementById('view');
  const ctx = canvas.getContext('2d');
  let W = 0;
  let H = 0;
  let s = 1;
  let ox = 0;
  let oy = 0;
  function fit() {
    const m = 10;
    s = Math.min((W - 2 * m) / AW, (H - 2 * m) / AH);
    ox = (W - AW * s) / 2;
    oy = (H - AH * s) / 2;
  }
  function resize(width, height) {
    const dpr = mode === 'live' ? window.devicePixelRatio || 1 : 1;
    W = width;
    H = height;
    canvas.width = Math.round(W * dpr);
    canvas.height = Math.round(H * dpr);
    canvas.style.width = W + 'px';
    canvas.style.height = H + 'px';
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  }
  const X = (x) => ox + x * s;
  const Y = (y) => oy + (AH - y) * s;

  // ---- drawing ------------------------------------------------------------------------------
  const showLabel = params.get('label') !== '0';
  const trail = Math.max(1.0, 2 * meta.frame_s);  // seconds a message line stays
  let hovered = -1;

  function drawArena() {
    ctx.fillStyle = '#eceae4';
    ctx.fillRect(0, 0, W, H);
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(X(0), Y(AH), AW * s, AH * s);
    ctx.strokeStyle = '#333';
    ctx.lineWidth = 1;
    ctx.strokeRect(X(0), Y(AH), AW * s, AH * s);
    ctx.fillStyle = '#8a8a8a';
    for (const [x0, y0, x1, y1] of meta.arena.obstacles) {
      ctx.fillRect(X(x0), Y(y1), (x1 - x0) * s, (y1 - y0) * s);
    }
  }

  function drawMovables() {
    const list = meta.arena.movables;
    if (!list.length) return;
    ctx.fillStyle = '#b58b4c';
    for (let k = 0; k < list.length; k++) {
      const o = list[k];
      let x = o.x_m;
      let y = o.y_m;
      let h = o.heading_rad;
      if (A.mov) {
        const i = (frameA * list.length + k) * 3;
        x = A.mov[i];
        y = A.mov[i + 1];
        h = A.mov[i + 2];
      }
      ctx.save();
      ctx.translate(X(x), Y(y));
      ctx.rotate(-h);
      if (o.shape === 'cylinder') {
        ctx.beginPath();
        ctx.arc(0, 0, Math.max(2, o.radius_m * s), 0, 2 * Math.PI);
        ctx.fill();
      } else {
        const w = Math.max(2, o.size_x_m * s);
        const d = Math.max(2, o.size_y_m * s);
        ctx.fillRect(-w / 2, -d / 2, w, d);
      }
      ctx.restore();
    }
  }

  // The world objects' latest rows up to t, by id.
  function objectsAt(t) {
    const shown = new Map();
    const end = upper(A.obj_t || [], t);
    for (let i = 0; i < end; i++) {
      if (A.obj_state[i] === 65535) shown.delete(A.obj_id[i]); else shown.set(A.obj_id[i], i);
    }
    return shown;
  }

  function drawObjects(t) {
    if (!objCount) return;
    ctx.font = '11px sans-serif';
    ctx.textAlign = 'center';
    for (const [id, i] of objectsAt(t)) {
      const c = colour(A.obj_state[i]);
      const r = Math.max(4, A.obj_r[i] * s);
      ctx.beginPath();
      ctx.arc(X(A.obj_x[i]), Y(A.obj_y[i]), r, 0, 2 * Math.PI);
      ctx.globalAlpha = 0.25;
      ctx.fillStyle = c;
      ctx.fill();
      ctx.globalAlpha = 1;
      ctx.strokeStyle = c;
      ctx.lineWidth = 2;
      ctx.stroke();
      if (r > 6) {
        ctx.fillStyle = '#333';
        ctx.fillText(meta.kinds[A.obj_kind[i]] + ' ' + id, X(A.obj_x[i]), Y(A.obj_y[i]) - r - 3);
      }
    }
  }

  // Pairs within `linkRange` metres (a grid of cells of that size finds them): green when a
  // message hopped between the two in the last `trail` seconds, else faint grey.
  let showLinks = params.get('links') === '1';
  let linkRange = Number(params.get('range') || meta.link_range_m || 0);
  function drawLinks(t) {
    if (!showLinks || !(linkRange > 0)) return;
    const recent = new Set();
    if (evCount) {
      const end = upper(A.ev_t, t);
      for (let i = upper(A.ev_t, t - trail); i < end; i++) {
        const a = A.ev_from[i];
        const b = A.ev_to[i];
        if (a !== b) recent.add(Math.min(a, b) * N + Math.max(a, b));
      }
    }
    const cells = new Map();
    for (let k = 0; k < N; k++) {
      const key = Math.floor(px[k] / linkRange) * 65536 + Math.floor(py[k] / linkRange);
      let list = cells.get(key);
      if (!list) cells.set(key, (list = []));
      list.push(k);
    }
    const r2 = linkRange * linkRange;
    const quiet = new Path2D();
    const busy = new Path2D();
    for (let a = 0; a < N; a++) {
      const cx = Math.floor(px[a] / linkRange);
      const cy = Math.floor(py[a] / linkRange);
      for (let dx = -1; dx <= 1; dx++) {
        for (let dy = -1; dy <= 1; dy++) {
          const list = cells.get((cx + dx) * 65536 + cy + dy);
          if (!list) continue;
          for (const b of list) {
            if (b <= a) continue;
            const ex = px[a] - px[b];
            const ey = py[a] - py[b];
            if (ex * ex + ey * ey > r2) continue;
            const path = recent.has(a * N + b) ? busy : quiet;
            path.moveTo(X(px[a]), Y(py[a]));
            path.lineTo(X(px[b]), Y(py[b]));
          }
        }
      }
    }
    ctx.lineWidth = 1;
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.08)';
    ctx.stroke(quiet);
    ctx.strokeStyle = 'rgba(20, 150, 40, 0.35)';
    ctx.stroke(busy);
  }

  // Messages in (t - trail, t]: forward hops grey, deliveries green, drops red crosses where the
  // packet died; older is fainter (four steps of fading, one path each).
  const kindStyle = ['rgba(184,134,11,A)', 'rgba(90,90,90,A)', 'rgba(20,150,40,A)', 'rgba(210,30,30,A)'];
  function drawMessages(t) {
    if (!evCount) return;
    const end = upper(A.ev_t, t);
    const begin = upper(A.ev_t, t - trail);
    for (let bucket = 3; bucket >= 0; bucket--) {
      const alpha = (0.25 + 0.75 * (1 - bucket / 4)).toFixed(2);
      for (let kind = 0; kind < 4; kind++) {
        ctx.strokeStyle = kindStyle[kind].replace('A', alpha);
        ctx.lineWidth = kind === 3 ? 2 : 1.5;
        ctx.beginPath();
        let any = false;
        for (let i = begin; i < end; i++) {
          if (A.ev_kind[i] !== kind) continue;
          const age = (t - A.ev_t[i]) / trail;
          if (Math.min(3, Math.floor(age * 4)) !== bucket) continue;
          any = true;
          const a = A.ev_from[i];
          const b = A.ev_to[i];
          if (kind === 3) {
            const x = X(px[b]);
            const y = Y(py[b]);
            ctx.moveTo(x - 4, y - 4); ctx.lineTo(x + 4, y + 4);
            ctx.moveTo(x - 4, y + 4); ctx.lineTo(x + 4, y - 4);
          } else if (kind === 0) {
            ctx.moveTo(X(px[b]) + 6, Y(py[b]));
            ctx.arc(X(px[b]), Y(py[b]), 6, 0, 2 * Math.PI);
          } else {
            ctx.moveTo(X(px[a]), Y(py[a]));
            ctx.lineTo(X(px[b]), Y(py[b]));
          }
        }
        if (any) ctx.stroke();
      }
    }
  }

  function drawRobots() {
    const r = Math.max(3, meta.robot_radius_m * s);
    const st = A.state;
    const groups = st ? states.length : 1;
    const base = frameA * N;
    for (let g = 0; g < groups; g++) {
      ctx.fillStyle = colour(g);
      ctx.strokeStyle = colour(g);
      ctx.lineWidth = 1.5;
      const body = new Path2D();
      const nose = new Path2D();
      let any = false;
      for (let k = 0; k < N; k++) {
        if (st && st[base + k] !== g) continue;
        any = true;
        const x = X(px[k]);
        const y = Y(py[k]);
        const h = (A.heading[base + k] * Math.PI * 2) / 256;
        const c = Math.cos(h);
        const sn = -Math.sin(h);
        body.moveTo(x + r, y);
        body.arc(x, y, r, 0, 2 * Math.PI);
        nose.moveTo(x + c * r, y + sn * r);
        nose.lineTo(x + c * (r + 4), y + sn * (r + 4));
      }
      if (any) {
        ctx.fill(body);
        ctx.stroke(nose);
      }
    }
    if (hovered >= 0) {
      ctx.strokeStyle = '#000';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(X(px[hovered]), Y(py[hovered]), r + 4, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }

  function drawLabel(t) {
    if (!showLabel) return;
    const text = 't = ' + t.toFixed(1) + ' s';
    ctx.font = '13px sans-serif';
    ctx.textAlign = 'left';
    const w = ctx.measureText(text).width + 10;
    ctx.fillStyle = 'rgba(255,255,255,0.85)';
    ctx.fillRect(4, 4, w, 20);
    ctx.fillStyle = '#222';
    ctx.fillText(text, 9, 19);
  }

  function draw(t) {
    positionsAt(t);
    drawArena();
    drawMovables();
    drawObjects(t);
    drawLinks(t);
    drawMessages(t);
    drawRobots();
    drawLabel(t);
  }

  // ---- modes --------------------------------------------------------------------------------
  if (mode !== 'live') {
    document.body.classList.add('bare');
    resize(num('w', 1280), num('h', 720));
    fit();
  }

  if (mode === 'still') {
    draw(Math.max(0, Math.min(duration, num('t', 0))));
    status.textContent = 'ok';
    return;
  }
  if (mode === 'frames') {
    const from = num('from', 0);
    const fps = num('fps', 30);
    const first = num('first', 0);
    const count = num('count', 1);
    const lines = [];
    for (let k = first; k < first + count; k++) {
      draw(Math.min(duration, from + k / fps));
      lines.push(canvas.toDataURL('image/png'));
    }
    document.getElementById('out').textContent = lines.join('\n');
    status.textContent = 'ok';
    return;
  }
  if (mode === 'bench') {
    draw(0);
    ctx.getImageData(0, 0, 1, 1);
    const opened = performance.now();  // navigation start to data decoded and a frame drawn
    const count = num('n', 300);
    const start = performance.now();
    for (let k = 0; k < count; k++) draw((duration * k) / count);
    ctx.getImageData(0, 0, 1, 1);  // waits for the drawing to be done
    const ms = (performance.now() - start) / count;
    document.getElementById('out').textContent = JSON.stringify({
      open_ms: opened, frame_ms: ms, fps: 1000 / ms, robots: N, frames: F,
      events: evCount, blob_bytes: bytes.length,
    });
    status.textContent = 'ok';
    return;
  }

  // ---- interactive --------------------------------------------------------------------------
  const stage = document.getElementById('stage');
  const slider = document.getElementById('slider');
  const clock = document.getElementById('clock');
  const playButton = document.getElementById('play');
  const speed = document.getElementById('speed');
  const tip = document.getElementById('tip');
  slider.max = duration;
  let t = Math.max(0, Math.min(duration, num('t', 0)));
  let playing = false;
  let last = 0;

  document.getElementById('title').textContent = meta.name;
  const facts = [N + ' robots', duration.toFixed(1) + ' s simulated', 'step ' + meta.step_s + ' s',
    F + ' frames of ' + meta.frame_s.toFixed(3) + ' s'];
  if (meta.summary.pdr !== null && meta.summary.pdr !== undefined) {
    facts.push('delivery ratio ' + Number(meta.summary.pdr).toFixed(3));
  }
  document.getElementById('facts').textContent = facts.join(' · ');
  const legend = document.getElementById('legend');
  const addLegend = (c, text, shape) => {
    const li = document.createElement('li');
    const sw = document.createElement('span');
    sw.className = 'swatch';
    sw.style.background = c;
    if (shape === 'disc') sw.style.borderRadius = '50%';
    li.append(sw, text);
    legend.append(li);
  };
  if (A.state || objCount) {
    states.forEach((label, i) => addLegend(colour(i), label === '' ? 'robot (no state)' : label, 'disc'));
  } else {
    addLegend(colour(0), 'robot', 'disc');
  }
  if (evCount) {
    addLegend('rgb(90,90,90)', 'hop of a message (relay)');
    addLegend('rgb(20,150,40)', 'delivery (last hop)');
    addLegend('rgb(210,30,30)', 'lost: where a copy died (reasons below)');
    addLegend('rgb(184,134,11)', 'message sent (ring)');
  }
  addLegend('rgba(20,150,40,0.5)', 'link (links box): a message hopped in the last second');
  const notes = [];
  if (meta.events && meta.events.kept_every > 1) {
    notes.push('Packet events thinned: 1 in ' + meta.events.kept_every + ' drawn.');
  }
  if (meta.events && meta.events.reasons.length) notes.push('Drop reasons: ' + meta.events.reasons.join(', ') + '.');
  if (meta.frame_s > meta.step_s) notes.push('Positions every ' + meta.frame_s.toFixed(2) + ' s, interpolated.');
  notes.push('Headings: ' + meta.headings + '. Wheel: zoom; drag: pan; hover a robot for details.');
  document.getElementById('notes').textContent = notes.join(' ');

  // The panel's chart: the network's delivery ratio (0..1, green) and mean delay (orange) per
  // interval, or one series the plugins sampled (series.csv): its mean over robots per interval
  // (blue) between the least and greatest value (shaded).
  const chart = document.getElementById('chart');
  const cctx = chart.getContext('2d');
  const pick = document.getElementById('chart-pick');
  const chartNote = document.getElementById('chart-note');
  const sampled = meta.series ? meta.series.series : [];
  const addChoice = (value, text) => {
    const option = document.createElement('option');
    option.value = value;
    option.textContent = text;
    pick.appendChild(option);
  };
  addChoice('delivery', 'Delivery ratio and delay');
  sampled.forEach((s, i) => addChoice(String(i), 'Series: ' + s.name));
  if (!meta.panel && sampled.length) pick.value = '0';
  pick.onchange = () => render();
  function chartFrame() {
    const cw = chart.width;
    const ch = chart.height;
    cctx.fillStyle = '#fff';
    cctx.fillRect(0, 0, cw, ch);
    cctx.strokeStyle = '#ccc';
    cctx.strokeRect(0.5, 0.5, cw - 1, ch - 1);
    cctx.font = '10px sans-serif';
    return [cw, ch];
  }
  function line(values, bx, yOf, c) {
    cctx.strokeStyle = c;
    cctx.lineWidth = 1.5;
    cctx.beginPath();
    let pen = false;
    for (let i = 0; i < values.length; i++) {
      if (values[i] === null) { pen = false; continue; }
      const y = yOf(values[i]);
      if (pen) cctx.lineTo(bx(i), y); else cctx.moveTo(bx(i), y);
      pen = true;
    }
    cctx.stroke();
  }
  function nowLine(cw, ch) {
    const x = (t / duration) * (cw - 10) + 5;
    cctx.strokeStyle = '#000';
    cctx.lineWidth = 1;
    cctx.beginPath();
    cctx.moveTo(x, 0);
    cctx.lineTo(x, ch);
    cctx.stroke();
  }
  function drawDelivery() {
    const [cw, ch] = chartFrame();
    chartNote.textContent = 'Messages sent in each interval: the share that reached a ' +
        'destination (green, 0–1) and their mean delay (orange, right scale).';
    const panel = meta.panel;
    if (!panel) {
      cctx.fillStyle = '#888';
      cctx.fillText('no packet trace in this run', 10, 20);
      return;
    }
    const bx = (i) => ((i + 0.5) * panel.bin_s / duration) * (cw - 10) + 5;
    const maxDelay = Math.max(1e-9, ...panel.delay_s.filter((d) => d !== null));
    line(panel.delivery_ratio, bx, (v) => ch - 5 - v * (ch - 20), '#2ca02c');
    line(panel.delay_s, bx, (v) => ch - 5 - (v / maxDelay) * (ch - 20), '#ff7f0e');
    cctx.fillStyle = '#555';
    cctx.fillText('ratio 1', 4, 12);
    cctx.textAlign = 'right';
    cctx.fillText('delay ' + (maxDelay * 1000).toFixed(1) + ' ms', cw - 4, 12);
    cctx.textAlign = 'left';
    nowLine(cw, ch);
  }
  function drawSeries(s) {
    const [cw, ch] = chartFrame();
    const bin = meta.series.bin_s;
    const shown = s.low.filter((v) => v !== null).concat(s.high.filter((v) => v !== null));
    let lo = Math.min(...shown);
    let hi = Math.max(...shown);
    if (hi - lo < 1e-12) { lo -= 0.5; hi += 0.5; }
    const bx = (i) => ((i + 0.5) * bin / duration) * (cw - 10) + 5;
    const yOf = (v) => ch - 5 - ((v - lo) / (hi - lo)) * (ch - 20);
    cctx.fillStyle = 'rgba(31,119,180,0.18)';
    for (let i = 0; i < s.mean.length; i++) {
      if (s.mean[i] === null) continue;
      const w = Math.max(1, (bin / duration) * (cw - 10));
      cctx.fillRect(bx(i) - w / 2, yOf(s.high[i]), w, Math.max(1, yOf(s.low[i]) - yOf(s.high[i])));
    }
    line(s.mean, bx, yOf, '#1f77b4');
    cctx.fillStyle = '#555';
    cctx.fillText(String(Number(hi.toPrecision(4))), 4, 12);
    cctx.fillText(String(Number(lo.toPrecision(4))), 4, ch - 8);
    const at = Math.min(s.mean.length - 1, Math.floor(t / bin));
    cctx.textAlign = 'right';
    cctx.fillText(s.mean[at] === null ? 'no sample now' : 'now ' + Number(s.mean[at].toPrecision(4)),
                  cw - 4, 12);
    cctx.textAlign = 'left';
    nowLine(cw, ch);
    const more = meta.series.not_shown ? ' ' + meta.series.not_shown + ' more series in ' +
        'series.csv are not offered here.' : '';
    chartNote.textContent = 'Series ' + s.name + ' (series.csv): its mean over the robots ' +
        'that sampled it in each ' + bin.toPrecision(3) + ' s interval (blue), between the ' +
        'least and greatest value (shaded).' + more;
  }
  function drawChart() {
    if (pick.value === 'delivery') drawDelivery(); else drawSeries(sampled[Number(pick.value)]);
  }

  function layout() {
    resize(stage.clientWidth, stage.clientHeight);
  }
  function render() {
    draw(t);
    slider.value = t;
    clock.textContent = t.toFixed(2) + ' / ' + duration.toFixed(1) + ' s';
    drawChart();
    status.textContent = 'ok';
  }
  function tick(now) {
    if (!playing) return;
    const dt = last ? (now - last) / 1000 : 1 / 60;  // the first frame after play: one 60th
    last = now;
    t = Math.min(duration, t + dt * Number(speed.value));
    if (t >= duration) setPlaying(false);
    render();
    if (playing) requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    playing = on;
    playButton.innerHTML = on ? '&#10074;&#10074;' : '&#9654;';
    if (on) {
      if (t >= duration) t = 0;
      last = 0;
      requestAnimationFrame(tick);
    }
  }
  const stepFrame = (k) => {
    setPlaying(false);
    t = Math.max(0, Math.min(duration, (Math.round(t / meta.frame_s) + k) * meta.frame_s));
    render();
  };
  playButton.onclick = () => setPlaying(!playing);
  document.getElementById('back').onclick = () => stepFrame(-1);
  document.getElementById('fwd').onclick = () => stepFrame(1);
  document.getElementById('fit').onclick = () => { fit(); render(); };
  const linksBox = document.getElementById('links');
  const rangeBox = document.getElementById('range');
  linksBox.checked = showLinks;
  rangeBox.value = linkRange > 0 ? linkRange : '';
  linksBox.onchange = () => { showLinks = linksBox.checked; render(); };
  rangeBox.onchange = () => { linkRange = Number(rangeBox.value); render(); };
  slider.oninput = () => { t = Number(slider.value); render(); };
  window.addEventListener('keydown', (e) => {
    if (e.key === ' ') { setPlaying(!playing); e.preventDefault(); }
    if (e.key === 'ArrowLeft') stepFrame(-1);
    if (e.key === 'ArrowRight') stepFrame(1);
    if (e.key === 'f') { fit(); render(); }
  });
  window.addEventListener('resize', () => { layout(); fit(); render(); });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const k = Math.exp(-e.deltaY * 0.0015);
    ox = e.offsetX - (e.offsetX - ox) * k;
    oy = e.offsetY - (e.offsetY - oy) * k;
    s *= k;
    render();
  }, { passive: false });
  let drag = null;
  canvas.addEventListener('mousedown', (e) => { drag = [e.clientX, e.clientY]; });
  window.addEventListener('mouseup', () => { drag = null; });
  canvas.addEventListener('mousemove', (e) => {
    if (drag) {
      ox += e.clientX - drag[0];
      oy += e.clientY - drag[1];
      drag = [e.clientX, e.clientY];
      render();
      return;
    }
    let best = -1;
    let bestD = 100;  // within 10 pixels
    for (let k = 0; k < N; k++) {
      const dx = X(px[k]) - e.offsetX;
      const dy = Y(py[k]) - e.offsetY;
      const d = dx * dx + dy * dy;
      if (d < bestD) { bestD = d; best = k; }
    }
    if (best !== hovered) {
      hovered = best;
      if (!playing) render();
    }
    if (best < 0) { tip.hidden = true; return; }
    const lines = ['robot ' + best, 'x ' + px[best].toFixed(2) + ' m, y ' + py[best].toFixed(2) + ' m'];
    if (A.state) lines.push('state ' + (states[A.state[frameA * N + best]] || '(none)'));
    if (A.r_sent) {
      // Up to now, from the events drawn (all of them unless thinned); over the run, exact.
      const counts = [0, 0, 0, 0];
      const end = upper(A.ev_t, t);
      for (let i = 0; i < end; i++) if (A.ev_to[i] === best) counts[A.ev_kind[i]]++;
      const thinned = meta.events.kept_every > 1 ? ' (1 in ' + meta.events.kept_every + ')' : '';
      lines.push('messages so far' + thinned + ': sent ' + counts[0] + ', received ' + counts[2] +
        ', relayed ' + counts[1] + ', dropped here ' + counts[3]);
      lines.push('over the run: sent ' + A.r_sent[best] + ', received ' + A.r_recv[best] +
        ', relayed ' + A.r_fwd[best] + ', dropped here ' + A.r_drop[best]);
    }
    tip.textContent = lines.join('\n');
    tip.style.left = (e.offsetX + 14) + 'px';
    tip.style.top = (e.offsetY + 14) + 'px';
    tip.hidden = false;
  });
  canvas.addEventListener('mouseleave', () => { tip.hidden = true; });
  layout();
  fit();
  render();
  if (params.get('play') === '1') setPlaying(true);
})();
