// The playground's page script: input and drawing only. Which pixels an algorithm writes, and
// which the oracle covers, comes from the chapters' C++ compiled to WebAssembly
// (playground_api.cpp through playground_module.js); nothing here decides coverage.
(function () {
  'use strict';

  // The grid sizes the page offers; the C++ side refuses anything larger.
  const MIN_WIDTH = 8;
  const MAX_WIDTH = 64;
  const MIN_HEIGHT = 8;
  const MAX_HEIGHT = 48;
  const MAX_PIXELS = MAX_WIDTH * MAX_HEIGHT;
  const SUBPIXEL = 1 / 256;
  const MARGIN = 1;  // cells shown around the grid, so a vertex can sit just outside it
  const SLOW_MS = 100;
  const NAMES = 'ABCDEF';
  // Okabe-Ito colours, as the chapters' pixel diagrams use (docs/DESIGN.md section 11).
  const FILL = ['#E69F00', '#56B4E9'];
  const EDGE = ['#7a4f00', '#1d5f85'];
  const MISSED = '#D55E00';
  const EXTRA = '#CC79A7';
  const TWICE = '#000000';
  // The scene's triangle colours, the ones playground_api.cpp draws with.
  const SCENE_COLORS = ['230 159 0', '86 180 233'];

  // Each preset: a grid, points, and two triangles as three point indices each.
  const PRESETS = [
    {title: 'Two triangles sharing an edge', width: 24, height: 20,
     points: [[3, 3], [20, 5], [8, 18], [22, 17]], triangles: [[0, 1, 2], [1, 3, 2]]},
    {title: "tinyrenderer's red and white triangles, scaled by 0.24 to whole pixels",
     width: 48, height: 48,
     points: [[2, 17], [12, 38], [17, 19], [43, 12], [36, 0], [17, 43]],
     triangles: [[0, 1, 2], [3, 4, 5]]},
    {title: "Gambetta's Figure 7-1, scaled by 1/12.5 (centred view), and a neighbour on P1P2",
     width: 48, height: 48,
     points: [[8, 4], [40, 28], [26, 44], [44, 44]], triangles: [[0, 1, 2], [1, 3, 2]]},
    {title: 'A needle less than a pixel tall, and a neighbour on its long edge',
     width: 64, height: 16,
     points: [[1.5, 9.75], [62, 10.5], [1.5, 10.25], [30, 3]], triangles: [[0, 1, 2], [0, 3, 1]]},
    {title: 'Vertices on pixel centres: a rectangle split along a diagonal through centres',
     width: 24, height: 20,
     points: [[4, 4], [20, 4], [20, 16], [4, 16]], triangles: [[0, 1, 2], [0, 2, 3]]},
    {title: 'A flat bottom and a flat top: where the published scanline loops divide by zero ' +
         '(chapters 03, 04)',
     width: 24, height: 20,
     points: [[4, 4], [20, 4], [12, 16], [20, 16]], triangles: [[0, 1, 2], [1, 3, 2]]},
    {title: 'Three vertices on one line beside a real triangle: the zero area the published ' +
         'barycentric fill divides by (chapter 06)',
     width: 24, height: 20,
     points: [[4, 4], [12, 10], [20, 16], [20, 4]], triangles: [[0, 1, 2], [0, 3, 2]]},
    {title: 'Huge coordinates: two vertices at \u00b12^30 whose shared edge crosses the grid',
     width: 32, height: 24,
     points: [[-1073741824, 4], [1073741824, 12.5], [16, 28], [16, -4]],
     triangles: [[0, 1, 2], [1, 0, 3]]},
  ];

  const $ = (id) => document.getElementById(id);
  const status = $('pg-status');

  if (typeof createPlaygroundModule !== 'function') {
    status.classList.add('pg-unavailable');
    status.textContent = 'The playground was not built: ' +
        (window.playgroundUnavailable || 'its WebAssembly module did not load') +
        '. To build it, install Emscripten (sudo apt-get install emscripten) and build the ' +
        'site again (./tutorial.sh run), with the CMake cache variable TUTORIAL_PLAYGROUND ' +
        'at AUTO, its default, or ON (cmake --preset release -DTUTORIAL_PLAYGROUND=AUTO).';
    window.playground = {ready: Promise.resolve(false)};
    return;
  }

  // ---- the WebAssembly side --------------------------------------------------------------

  class Library {
    constructor(module) {
      this.module = module;
      const length = module._playground_algorithms(0, 0);
      const text = this.withBuffer(length + 1, (pointer) => {
        module._playground_algorithms(pointer, length + 1);
        return module.UTF8ToString(pointer);
      });
      this.algorithms = text.split('\n').filter((line) => line).map((line) => {
        const [name, chapter, rule, threaded, summary] = line.split('\t');
        return {name, chapter, rule, threaded: threaded === '1', summary};
      });
      // Buffers owned by the page, sized for the largest grid, reused by every draw.
      this.name = module._malloc(256);
      this.vertices = module._malloc(12 * 8);
      this.counts = module._malloc(MAX_PIXELS * 4);
      this.last = module._malloc(MAX_PIXELS);
      this.oracleCounts = module._malloc(MAX_PIXELS * 4);
      this.oracleLast = module._malloc(MAX_PIXELS);
      this.outside = module._malloc(2 * 4);
      this.message = module._malloc(512);
      this.coverageValues = module._malloc(MAX_PIXELS * 2);
      this.exactValues = module._malloc(MAX_PIXELS * 2);
      this.rgba = module._malloc(MAX_PIXELS * 4);
    }

    withBuffer(size, use) {
      const pointer = this.module._malloc(size);
      try {
        return use(pointer);
      } finally {
        this.module._free(pointer);
      }
    }

    // Draws the triangles (12 numbers) with `name` and with the oracle; returns the results, or
    // {error} when the library refuses the input.
    draw(name, width, height, vertices) {
      const m = this.module;
      m.stringToUTF8(name, this.name, 256);
      m.HEAPF64.set(vertices, this.vertices / 8);
      const code = m._playground_draw(this.name, width, height, this.vertices, this.counts,
                                      this.last, this.oracleCounts, this.oracleLast,
                                      this.outside, this.message, 512);
      if (code !== 0) return {error: m.UTF8ToString(this.message)};
      const n = width * height;
      // The heap may have grown (and its views been replaced) during the call.
      return {
        counts: m.HEAPU32.slice(this.counts / 4, this.counts / 4 + n),
        last: m.HEAPU8.slice(this.last, this.last + n),
        oracleCounts: m.HEAPU32.slice(this.oracleCounts / 4, this.oracleCounts / 4 + n),
        oracleLast: m.HEAPU8.slice(this.oracleLast, this.oracleLast + n),
        outside: Array.from(m.HEAPU32.slice(this.outside / 4, this.outside / 4 + 2)),
      };
    }

    // Chapter 03's arrays for triangle 1 (playground_steps_03), or null.
    steps03(width, height, vertices) {
      const m = this.module;
      m.HEAPF64.set(vertices, this.vertices / 8);
      const length = m._playground_steps_03(width, height, this.vertices, 0, 0);
      if (length === 0) return null;
      return JSON.parse(this.withBuffer(length + 1, (pointer) => {
        m._playground_steps_03(width, height, this.vertices, pointer, length + 1);
        return m.UTF8ToString(pointer);
      }));
    }

    // Chapter 04's step `step` (1 to 6) drawn by the chapter's own function on triangle 1: the
    // canvas's RGBA bytes, bottom row first, or null.
    steps04(step, width, height, vertices) {
      const m = this.module;
      m.HEAPF64.set(vertices, this.vertices / 8);
      const code = m._playground_steps_04(step, width, height, this.vertices, this.rgba);
      return code === 0 ? m.HEAPU8.slice(this.rgba, this.rgba + width * height * 4) : null;
    }

    // The coverage (rule area) of the triangles by `name` and by chapter 09's exact area, each
    // pixel as raster --coverage's 16-bit value; or {error}.
    coverage(name, width, height, vertices) {
      const m = this.module;
      m.stringToUTF8(name, this.name, 256);
      m.HEAPF64.set(vertices, this.vertices / 8);
      const code = m._playground_coverage(this.name, width, height, this.vertices,
                                          this.coverageValues, this.exactValues, this.message,
                                          512);
      if (code !== 0) return {error: m.UTF8ToString(this.message)};
      const n = width * height;
      return {
        area: true,
        coverage: m.HEAPU16.slice(this.coverageValues / 2, this.coverageValues / 2 + n),
        exact: m.HEAPU16.slice(this.exactValues / 2, this.exactValues / 2 + n),
      };
    }
  }

  // ---- the page's state ------------------------------------------------------------------

  const state = {
    algorithm: '',
    width: 24,
    height: 20,
    // The text of each field, as typed; points hold the numbers when every field parses.
    points: [],
    triangles: [],
    selected: 0,
    result: null,   // the last drawing, or null when nothing is drawn
    steps: null,    // chapter 03's arrays for triangle 1, when its algorithm is selected
    stepPixels: null,  // chapter 04's step on triangle 1 (RGBA), when one of its is selected
    step: 0,        // 0: the registered algorithm's result; else the chapter's step shown
    error: '',
    milliseconds: 0,
  };

  // A coordinate as the scene format writes it: the shortest decimal that reads back as the
  // same double (JavaScript's own), without a '+' in the exponent.
  const formatNumber = (x) => String(x).replace('e+', 'e');

  // The scene format's numbers (docs/DESIGN.md section 4); NaN and infinities are passed on so
  // the library refuses them with its own message, as raster would refuse the scene.
  const DECIMAL = /^-?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/;
  function parseCoordinate(text) {
    const t = text.trim();
    if (DECIMAL.test(t)) return Number(t);
    if (/^[-+]?nan$/i.test(t)) return NaN;
    if (/^[-+]?inf(inity)?$/i.test(t)) return t.startsWith('-') ? -Infinity : Infinity;
    return undefined;
  }

  function loadPreset(index) {
    const preset = PRESETS[index];
    state.width = preset.width;
    state.height = preset.height;
    state.points = preset.points.map(([x, y]) => ({x, y, textX: formatNumber(x),
                                                     textY: formatNumber(y)}));
    state.triangles = preset.triangles;
    state.selected = 0;
    $('pg-width').value = String(preset.width);
    $('pg-height').value = String(preset.height);
    buildVertexTable();
    update();
  }

  // ---- input checking and drawing ----------------------------------------------------------

  function inputProblems() {
    const problems = [];
    const w = $('pg-width').value.trim();
    const h = $('pg-height').value.trim();
    const width = /^\d+$/.test(w) ? Number(w) : NaN;
    const height = /^\d+$/.test(h) ? Number(h) : NaN;
    const widthOk = width >= MIN_WIDTH && width <= MAX_WIDTH;
    const heightOk = height >= MIN_HEIGHT && height <= MAX_HEIGHT;
    $('pg-width').setAttribute('aria-invalid', String(!widthOk));
    $('pg-height').setAttribute('aria-invalid', String(!heightOk));
    if (!widthOk || !heightOk) {
      problems.push(`the grid must be ${MIN_WIDTH} to ${MAX_WIDTH} pixels wide and ` +
                    `${MIN_HEIGHT} to ${MAX_HEIGHT} high, not '${w}' \u00d7 '${h}'`);
    } else {
      state.width = width;
      state.height = height;
    }
    state.points.forEach((point, index) => {
      for (const axis of ['x', 'y']) {
        const text = point['text' + axis.toUpperCase()];
        const value = parseCoordinate(text);
        const field = $(`pg-${axis}${index}`);
        if (field) field.setAttribute('aria-invalid', String(!Number.isFinite(value)));
        if (value === undefined) {
          problems.push(`vertex ${NAMES[index]}, ${axis}: '${text.slice(0, 32)}' is not a number`);
        } else {
          point[axis] = value;
        }
      }
    });
    return problems;
  }

  function triangleVertices() {
    const vertices = [];
    for (const triangle of state.triangles) {
      for (const index of triangle) vertices.push(state.points[index].x, state.points[index].y);
    }
    return vertices;
  }

  const selectedAlgorithm = () =>
    library.algorithms.find((entry) => entry.name === state.algorithm);
  const isArea = () => selectedAlgorithm().rule === 'area';
  const isChapter03 = () => selectedAlgorithm().chapter.startsWith('03');
  const isChapter04 = () => selectedAlgorithm().chapter.startsWith('04');
  // A 16-bit coverage value (0 to 65535) as the fraction of a pixel.
  const UNIT = 65535;

  function update() {
    const problems = inputProblems();
    state.result = null;
    state.error = '';
    if (problems.length > 0) {
      state.error = 'Nothing is drawn: ' + problems.join('; ') + '.';
    } else {
      const start = performance.now();
      const result = (isArea() ? library.coverage : library.draw).call(
          library, state.algorithm, state.width, state.height, triangleVertices());
      state.milliseconds = performance.now() - start;
      state.steps = !result.error && isChapter03() ?
          library.steps03(state.width, state.height, triangleVertices()) : null;
      state.stepPixels = !result.error && isChapter04() && state.step > 0 ?
          library.steps04(state.step, state.width, state.height, triangleVertices()) : null;
      if (result.error) {
        state.error = 'Nothing is drawn: the library refuses this input (' + result.error +
                      '), as raster refuses the scene.';
      } else {
        state.result = result;
      }
    }
    if (state.error) {
      state.steps = null;
      state.stepPixels = null;
    }
    const message = $('pg-message');
    message.hidden = state.error === '';
    message.textContent = state.error;
    render();
    writeCounts();
    writeRasterBox();
    refreshVertexTable();
    writeSteps();
    if (hovered) $('pg-hover').textContent = describePixel(hovered);
  }

  // ---- chapter 03's steps ---------------------------------------------------------------------

  // The step lists: [value, title]; 0 is the registered algorithm's result on both triangles.
  const STEPS = {
    '03': [
      [1, '1 \u00b7 sort the vertices by y (rounded to pixel centres): P0, P1, P2'],
      [2, '2 \u00b7 x01, x12 and x02: each side\'s x at every row it spans (interpolate)'],
      [3, '3 \u00b7 x012: x01 without its last value, then x12'],
      [4, '4 \u00b7 x_left and x_right: x02 and x012 compared at the middle row'],
      [0, '5 \u00b7 the span of every row, x_left to x_right rounded: the result'],
    ],
    '04': [
      [1, '1 \u00b7 the outline: three Bresenham lines'],
      [2, '2 \u00b7 sorted by y: boundary A (t0 to t2, red) and boundary B (green)'],
      [3, '3 \u00b7 the lower half: one point on A and one on B per row'],
      [4, '4 \u00b7 the lower half filled between them'],
      [5, '5 \u00b7 two loops: the lower half, then the upper half'],
      [6, '6 \u00b7 one loop that switches boundary B at t1'],
      [0, 'the registered algorithm\'s result, both triangles'],
    ],
  };
  // The arrays each step shows, with their colours (Okabe-Ito).
  const STEP_ARRAYS = {
    2: [['x01', '#009E73'], ['x12', '#CC79A7'], ['x02', '#0072B2']],
    3: [['x012', '#D55E00'], ['x02', '#0072B2']],
    4: [['x_left', '#009E73'], ['x_right', '#D55E00']],
  };
  const showingSteps = () => state.steps !== null && state.step > 0;
  const showingStepPixels = () => state.stepPixels !== null && state.step > 0;
  const stepsChapter = () => (isChapter03() ? '03' : isChapter04() ? '04' : null);

  // Fills the step list for the selected algorithm's chapter (hidden for the others).
  function chooseStepList() {
    const chapter = stepsChapter();
    const select = $('pg-step');
    select.textContent = '';
    state.step = 0;
    $('pg-steps-title').textContent = chapter ? `Chapter ${chapter}'s steps, on triangle 1:` : '';
    for (const [value, title] of STEPS[chapter] || []) {
      const option = document.createElement('option');
      option.value = String(value);
      option.textContent = title;
      select.appendChild(option);
    }
    select.value = '0';
  }

  function writeSteps() {
    const box = $('pg-steps');
    box.hidden = !(state.result && stepsChapter());
    const steps = state.steps;
    if (box.hidden) return;
    if (isChapter04()) {
      $('pg-arrays').hidden = true;
      return;
    }
    $('pg-arrays').hidden = false;
    if (!steps || !steps.x02) {
      $('pg-arrays').textContent = steps ? 'Triangle 1 has no row on the grid: no arrays.' :
          'Triangle 1 lies on one row: the chapter draws it as one span, without the arrays.';
      return;
    }
    const format = (name) => {
      const a = steps[name];
      if (a.values.length === 0) return `${name} = [] (no row on the grid)`;
      const last = a.first + a.values.length - 1;
      const values = a.values.map((v) => Number.isInteger(v) ? String(v) : v.toFixed(2));
      return `${name} (rows ${a.first} to ${last}) = [${values.join(', ')}]`;
    };
    const p = steps.sorted;
    const lines = [`P0 = (${p[0]}), P1 = (${p[1]}), P2 = (${p[2]})`];
    for (const name of ['x01', 'x12', 'x02', 'x012', 'x_left', 'x_right']) {
      lines.push(format(name));
    }
    $('pg-arrays').textContent = lines.join('\n');
  }

  // Chapter 04's step: every pixel its function painted, in the colour it painted.
  function drawStepPixels(g) {
    const rgba = state.stepPixels;
    for (let j = 0; j < state.height; ++j) {
      for (let i = 0; i < state.width; ++i) {
        const k = 4 * (j * state.width + i);
        if (rgba[k] === 0 && rgba[k + 1] === 0 && rgba[k + 2] === 0) continue;
        g.fillStyle = `rgb(${rgba[k]}, ${rgba[k + 1]}, ${rgba[k + 2]})`;
        g.fillRect(toCanvasX(i - 0.5), toCanvasY(j + 0.5), cell, cell);
      }
    }
  }

  function drawSteps(g) {
    const steps = state.steps;
    const p = steps.sorted;
    g.font = 'bold 11px sans-serif';
    g.textAlign = 'left';
    g.textBaseline = 'bottom';
    p.forEach(([x, y], i) => {
      g.strokeStyle = '#000000';
      g.lineWidth = 2;
      g.beginPath();
      g.arc(toCanvasX(x), toCanvasY(y), cell * 0.42, 0, 2 * Math.PI);
      g.stroke();
      g.fillStyle = '#000000';
      g.fillText(`P${i}`, toCanvasX(x) + cell * 0.45, toCanvasY(y) - cell * 0.2);
    });
    for (const [name, colour] of STEP_ARRAYS[state.step] || []) {
      const a = steps[name];
      if (!a) continue;
      g.strokeStyle = colour;
      g.fillStyle = colour;
      g.lineWidth = 1.5;
      g.beginPath();
      a.values.forEach((x, i) => {
        const X = toCanvasX(x);
        const Y = toCanvasY(a.first + i);
        if (i === 0) g.moveTo(X, Y); else g.lineTo(X, Y);
      });
      g.stroke();
      a.values.forEach((x, i) => {
        g.beginPath();
        g.arc(toCanvasX(x), toCanvasY(a.first + i), Math.max(2.5, cell / 6), 0, 2 * Math.PI);
        g.fill();
      });
    }
    if (state.step === 4 && steps.x02 && steps.x02.values.length > 0) {
      // The row the chapter compares x02 and x012 at: floor(length / 2).
      const row = steps.x02.first + Math.floor(steps.x02.values.length / 2);
      g.strokeStyle = '#000000';
      g.setLineDash([4, 3]);
      g.beginPath();
      g.moveTo(toCanvasX(-0.5), toCanvasY(row));
      g.lineTo(toCanvasX(state.width - 0.5), toCanvasY(row));
      g.stroke();
      g.setLineDash([]);
    }
  }

  // ---- geometry of the views ---------------------------------------------------------------

  const views = [
    {canvas: $('pg-canvas-algorithm'), kind: 'algorithm'},
    {canvas: $('pg-canvas-oracle'), kind: 'oracle'},
  ];
  let cell = 16;

  function chooseCellSize() {
    const available = Math.max(200, $('pg').clientWidth - 8);
    const columns = state.width + 2 * MARGIN;
    const sideBySide = Math.floor((available - 24) / 2 / columns);
    cell = sideBySide >= 12 ? Math.min(sideBySide, 32)
                            : Math.max(6, Math.min(32, Math.floor(available / columns)));
  }

  const toCanvasX = (x) => (x + 0.5 + MARGIN) * cell;
  const toCanvasY = (y) => (state.height - 0.5 - y + MARGIN) * cell;
  const fromCanvasX = (px) => px / cell - 0.5 - MARGIN;
  const fromCanvasY = (py) => state.height - 0.5 + MARGIN - py / cell;

  // The part of segment p-q inside the view (Liang-Barsky), in grid units, or null. Drawn lines
  // stay short even when a vertex is 2^30 pixels away.
  function clipToView(p, q) {
    const lo = [-0.5 - MARGIN, -0.5 - MARGIN];
    const hi = [state.width - 0.5 + MARGIN, state.height - 0.5 + MARGIN];
    let t0 = 0;
    let t1 = 1;
    const d = [q.x - p.x, q.y - p.y];
    const s = [p.x, p.y];
    for (let axis = 0; axis < 2; ++axis) {
      for (const [bound, sign] of [[lo[axis], -1], [hi[axis], 1]]) {
        const denominator = sign * d[axis];
        const numerator = sign * (bound - s[axis]);
        if (denominator === 0) {
          if (numerator < 0) return null;
        } else {
          const t = numerator / denominator;
          if (denominator > 0) t1 = Math.min(t1, t); else t0 = Math.max(t0, t);
        }
      }
    }
    if (t0 > t1) return null;
    return [{x: p.x + t0 * d[0], y: p.y + t0 * d[1]}, {x: p.x + t1 * d[0], y: p.y + t1 * d[1]}];
  }

  const inView = (p) => Number.isFinite(p.x) && Number.isFinite(p.y) &&
      p.x >= -0.5 - MARGIN && p.x <= state.width - 0.5 + MARGIN &&
      p.y >= -0.5 - MARGIN && p.y <= state.height - 0.5 + MARGIN;

  // ---- drawing -------------------------------------------------------------------------------

  function render() {
    chooseCellSize();
    for (const view of views) renderView(view);
  }

  function renderView(view) {
    const canvas = view.canvas;
    const w = (state.width + 2 * MARGIN) * cell;
    const h = (state.height + 2 * MARGIN) * cell;
    const ratio = window.devicePixelRatio || 1;
    canvas.style.width = w + 'px';
    canvas.style.height = h + 'px';
    canvas.width = Math.round(w * ratio);
    canvas.height = Math.round(h * ratio);
    const g = canvas.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.fillStyle = '#eeeeee';
    g.fillRect(0, 0, w, h);
    g.fillStyle = '#ffffff';
    g.fillRect(MARGIN * cell, MARGIN * cell, state.width * cell, state.height * cell);

    const oracleView = view.kind === 'oracle';
    // While a chapter's step is shown, the algorithm's grid shows the step instead.
    const r = !oracleView && (showingSteps() || showingStepPixels()) ? null : state.result;
    if (!oracleView && showingStepPixels()) drawStepPixels(g);
    for (let j = 0; j < state.height; ++j) {
      for (let i = 0; i < state.width; ++i) {
        const left = toCanvasX(i - 0.5);
        const top = toCanvasY(j + 0.5);
        if (r && r.area) {
          const k = j * state.width + i;
          const value = oracleView ? r.exact[k] : r.coverage[k];
          if (value > 0) {
            g.fillStyle = coverageShade(value / UNIT);
            g.fillRect(left, top, cell, cell);
          }
          if (!oracleView) markCoverageDifference(g, left, top, r.coverage[k], r.exact[k]);
        } else if (r) {
          const k = j * state.width + i;
          const a = oracleView ? r.oracleCounts[k] : r.counts[k];
          const writer = oracleView ? r.oracleLast[k] : r.last[k];
          if (a > 0 && writer > 0) {
            g.fillStyle = FILL[writer - 1];
            g.fillRect(left, top, cell, cell);
          }
          if (!oracleView) markDifference(g, left, top, a, r.oracleCounts[k]);
        }
        g.strokeStyle = '#c8c8c8';
        g.lineWidth = 1;
        g.strokeRect(left + 0.5, top + 0.5, cell - 1, cell - 1);
        g.fillStyle = '#404040';
        g.beginPath();
        g.arc(left + cell / 2, top + cell / 2, Math.max(1.2, cell / 14), 0, 2 * Math.PI);
        g.fill();
      }
    }
    drawAxisNumbers(g);
    drawTriangles(g);
    if (!oracleView && showingSteps()) drawSteps(g);
  }

  // The marks of docs/DESIGN.md section 6: a cross where the algorithm misses a covered centre,
  // a ring where it writes a pixel the oracle does not cover, the count where it writes twice.
  function markDifference(g, left, top, a, t) {
    const c = cell;
    if (t > a) {
      g.strokeStyle = MISSED;
      g.lineWidth = Math.max(2, c / 8);
      g.beginPath();
      g.moveTo(left + c * 0.2, top + c * 0.2);
      g.lineTo(left + c * 0.8, top + c * 0.8);
      g.moveTo(left + c * 0.8, top + c * 0.2);
      g.lineTo(left + c * 0.2, top + c * 0.8);
      g.stroke();
    }
    if (a > t && t === 0) {
      g.strokeStyle = EXTRA;
      g.lineWidth = Math.max(2, c / 8);
      g.beginPath();
      g.arc(left + c / 2, top + c / 2, c * 0.36, 0, 2 * Math.PI);
      g.stroke();
    }
    if (a > 1) {
      g.fillStyle = TWICE;
      g.font = `bold ${Math.max(8, Math.floor(c * 0.45))}px sans-serif`;
      g.textAlign = 'right';
      g.textBaseline = 'top';
      g.fillText(String(a), left + c - 2, top + 1);
    }
  }

  // White to Okabe-Ito blue (0, 114, 178) in proportion to the coverage.
  function coverageShade(c) {
    const mix = (full) => Math.round(255 + (full - 255) * c);
    return `rgb(${mix(0)}, ${mix(114)}, ${mix(178)})`;
  }

  // More than one 16-bit unit from the exact area (docs/DESIGN.md section 6): a cross where the
  // coverage is too small, a ring where it is too large.
  function markCoverageDifference(g, left, top, a, t) {
    if (Math.abs(a - t) <= 1) return;
    markDifference(g, left, top, a < t ? 0 : 1, a < t ? 1 : 0);
  }

  function drawAxisNumbers(g) {
    if (cell < 10) return;
    g.fillStyle = '#555555';
    g.font = `${Math.min(11, Math.floor(cell * 0.6))}px sans-serif`;
    g.textAlign = 'center';
    g.textBaseline = 'middle';
    const step = cell >= 20 ? 2 : 4;
    for (let i = 0; i < state.width; i += step) {
      g.fillText(String(i), toCanvasX(i), toCanvasY(-0.5) + cell * MARGIN / 2);
    }
    for (let j = 0; j < state.height; j += step) {
      g.fillText(String(j), toCanvasX(-0.5) - cell * MARGIN / 2, toCanvasY(j));
    }
  }

  function drawTriangles(g) {
    state.triangles.forEach((triangle, t) => {
      g.strokeStyle = EDGE[t];
      g.lineWidth = 2;
      for (let e = 0; e < 3; ++e) {
        const p = state.points[triangle[e]];
        const q = state.points[triangle[(e + 1) % 3]];
        if (![p.x, p.y, q.x, q.y].every(Number.isFinite)) continue;
        const piece = clipToView(p, q);
        if (!piece) continue;
        g.beginPath();
        g.moveTo(toCanvasX(piece[0].x), toCanvasY(piece[0].y));
        g.lineTo(toCanvasX(piece[1].x), toCanvasY(piece[1].y));
        g.stroke();
      }
    });
    state.points.forEach((p, index) => {
      if (!inView(p)) return;
      const x = toCanvasX(p.x);
      const y = toCanvasY(p.y);
      g.fillStyle = index === state.selected ? '#0072B2' : '#ffffff';
      g.strokeStyle = '#000000';
      g.lineWidth = 1.5;
      g.beginPath();
      g.arc(x, y, 7, 0, 2 * Math.PI);
      g.fill();
      g.stroke();
      g.fillStyle = index === state.selected ? '#ffffff' : '#000000';
      g.font = 'bold 10px sans-serif';
      g.textAlign = 'center';
      g.textBaseline = 'middle';
      g.fillText(NAMES[index], x, y + 0.5);
    });
  }

  // ---- what the page writes out --------------------------------------------------------------

  function writeCounts() {
    const list = $('pg-counts');
    list.textContent = '';
    // One line of the list: strings and swatches in order.
    const item = (...parts) => {
      const li = document.createElement('li');
      for (const part of parts) {
        li.appendChild(typeof part === 'string' ? document.createTextNode(part) : part);
      }
      list.appendChild(li);
    };
    const swatch = (fill, border, mark) => {
      const s = document.createElement('span');
      s.className = 'pg-swatch';
      s.style.background = fill;
      s.style.borderColor = border;
      s.style.color = border;
      s.textContent = mark;
      return s;
    };
    const r = state.result;
    if (!r) {
      item('No pixels: nothing is drawn until every field holds a number the library accepts.');
      return;
    }
    if (r.area) {
      writeCoverageCounts(r, item, swatch);
      return;
    }
    let covered = 0;
    let writes = 0;
    let written = 0;
    let missed = 0;
    let extra = 0;
    let twice = 0;
    const perTriangle = [0, 0];
    for (let k = 0; k < r.counts.length; ++k) {
      const a = r.counts[k];
      const t = r.oracleCounts[k];
      covered += t;
      if (t > 0 && r.oracleLast[k] > 0) perTriangle[r.oracleLast[k] - 1] += t;
      writes += a;
      written += a > 0 ? 1 : 0;
      missed += Math.max(0, t - a);
      extra += Math.max(0, a - t);
      twice += a > 1 ? 1 : 0;
    }
    const pixels = (n) => `${n} pixel${n === 1 ? '' : 's'}`;
    item(`The oracle covers ${pixels(covered)}: `, swatch(FILL[0], '#777', ''),
         `${perTriangle[0]} of triangle 1, `, swatch(FILL[1], '#777', ''),
         `${perTriangle[1]} of triangle 2.`);
    item(`${state.algorithm} writes ${pixels(written)} (${writes} writes).`);
    item(swatch('#ffffff', MISSED, '\u00d7'),
         `Missed: ${missed} (a cross: a centre the oracle covers, not written).`);
    item(swatch('#ffffff', EXTRA, '\u25cb'),
         `Extra: ${extra} writes beyond the oracle's count (a ring: a pixel the oracle leaves ` +
         'empty).');
    item(swatch('#ffffff', TWICE, '2'),
         `Drawn twice or more: ${pixels(twice)} (the number of writes in the corner).`);
    const exact = missed === 0 && extra === 0;
    item((exact ? 'Exactly the oracle\'s pixels.' : 'Not the oracle\'s pixels.') +
         ` Writes off the grid: ${r.outside[0]} (oracle: ${r.outside[1]}). Both drawn in ` +
         `${state.milliseconds.toFixed(1)} ms` +
         (state.milliseconds > SLOW_MS ? ' \u2014 slow: a smaller grid redraws faster.' : '.'));
  }

  function writeCoverageCounts(r, item, swatch) {
    // Sums in 16-bit units; "off" means more than one unit from the exact area.
    const n = {exact: 0, drawn: 0, touched: 0, tooSmall: 0, tooLarge: 0, largest: 0};
    r.coverage.forEach((a, k) => {
      const t = r.exact[k];
      n.exact += t;
      n.drawn += a;
      n.touched += a > 0 ? 1 : 0;
      n.tooSmall += a + 1 < t ? 1 : 0;
      n.tooLarge += a > t + 1 ? 1 : 0;
      n.largest = Math.max(n.largest, Math.abs(a - t));
    });
    const area = (units) => (units / UNIT).toFixed(3);
    item(swatch(coverageShade(0.5), '#777', ''), `The exact area covers ${area(n.exact)} ` +
         'pixels\' worth on the grid (each pixel shaded by its coverage, summed over the two ' +
         'triangles and clamped to 1).');
    item(`${state.algorithm} covers ${area(n.drawn)} pixels' worth, touching ${n.touched} ` +
         'pixels.');
    item(swatch('#ffffff', MISSED, '\u00d7'), `Too little: ${n.tooSmall} pixels more than one ` +
         '16-bit unit (1/65535) below the exact area.');
    item(swatch('#ffffff', EXTRA, '\u25cb'),
         `Too much: ${n.tooLarge} pixels more than one unit above it.`);
    item(`Largest difference: ${n.largest} units (${area(n.largest)} of a pixel). Both drawn in ` +
         `${state.milliseconds.toFixed(1)} ms` +
         (state.milliseconds > SLOW_MS ? ' \u2014 slow: a smaller grid redraws faster.' : '.'));
  }

  function sceneText() {
    const lines = [`# The playground's two triangles (tools/playground): ${state.algorithm}, ` +
                   `${state.width}x${state.height}`, `canvas ${state.width} ${state.height}`];
    state.triangles.forEach((triangle, t) => {
      const numbers = triangle.flatMap((i) => [state.points[i].textX, state.points[i].textY]);
      lines.push(`tri ${numbers.map((text) => text.trim()).join(' ')} ${SCENE_COLORS[t]}`);
    });
    return lines.join('\n') + '\n';
  }

  let downloadUrl = null;
  function writeRasterBox() {
    const scene = sceneText();
    $('pg-scene').textContent = scene;
    $('pg-command').textContent =
        `./build/release/tools/raster --algo ${state.algorithm} --scene playground.scene ` +
        (isArea() ? '--coverage playground.pgm' : '--counts playground.pgm');
    if (downloadUrl) URL.revokeObjectURL(downloadUrl);
    downloadUrl = URL.createObjectURL(new Blob([scene], {type: 'text/plain'}));
    $('pg-download').href = downloadUrl;
  }

  // ---- the vertex table ------------------------------------------------------------------------

  function buildVertexTable() {
    const body = $('pg-vertices');
    body.textContent = '';
    state.points.forEach((point, index) => {
      const row = document.createElement('tr');
      row.id = `pg-row${index}`;
      const name = document.createElement('td');
      name.textContent = NAMES[index];
      row.appendChild(name);
      for (const axis of ['x', 'y']) {
        const cellElement = document.createElement('td');
        const field = document.createElement('input');
        field.type = 'text';
        field.inputMode = 'decimal';
        field.id = `pg-${axis}${index}`;
        field.setAttribute('aria-label', `vertex ${NAMES[index]}, ${axis}`);
        field.spellcheck = false;
        field.addEventListener('input', () => {
          point['text' + axis.toUpperCase()] = field.value;
          state.selected = index;
          update();
        });
        field.addEventListener('focus', () => {
          state.selected = index;
          refreshVertexTable();
          render();
        });
        field.addEventListener('keydown', (event) => {
          if (event.key !== 'ArrowUp' && event.key !== 'ArrowDown') return;
          event.preventDefault();
          const step = (event.shiftKey ? SUBPIXEL : 1) * (event.key === 'ArrowUp' ? 1 : -1);
          nudge(index, axis === 'x' ? step : 0, axis === 'y' ? step : 0);
        });
        cellElement.appendChild(field);
        row.appendChild(cellElement);
      }
      const used = document.createElement('td');
      used.textContent = state.triangles.map((triangle, t) => triangle.includes(index) ?
          `triangle ${t + 1}` : '').filter((text) => text).join(', ');
      row.appendChild(used);
      row.addEventListener('click', () => {
        state.selected = index;
        refreshVertexTable();
        render();
      });
      body.appendChild(row);
    });
    refreshVertexTable();
  }

  // Shows each point's text in its fields, leaving alone the field being typed in.
  function refreshVertexTable() {
    state.points.forEach((point, index) => {
      for (const axis of ['x', 'y']) {
        const field = $(`pg-${axis}${index}`);
        const text = point['text' + axis.toUpperCase()];
        if (field && document.activeElement !== field && field.value !== text) {
          field.value = text;
        }
      }
      const row = $(`pg-row${index}`);
      if (row) row.classList.toggle('pg-selected', index === state.selected);
    });
  }

  function setPoint(index, x, y) {
    const point = state.points[index];
    point.x = x;
    point.y = y;
    point.textX = formatNumber(x);
    point.textY = formatNumber(y);
    for (const axis of ['x', 'y']) {
      const field = $(`pg-${axis}${index}`);
      if (field) field.value = point['text' + axis.toUpperCase()];
    }
    update();
  }

  function nudge(index, dx, dy) {
    const point = state.points[index];
    if (!Number.isFinite(point.x) || !Number.isFinite(point.y)) return;
    // Whole steps stay on the 1/256 grid: round the sum to it.
    const snap = (v) => Math.round(v * 256) / 256;
    setPoint(index, snap(point.x + dx), snap(point.y + dy));
  }

  // ---- mouse and keyboard on the grids ---------------------------------------------------------

  let dragging = null;
  let hovered = null;  // the pointer's last place on a grid, so its line follows every redraw

  function pointerPosition(canvas, event) {
    const box = canvas.getBoundingClientRect();
    return {x: event.clientX - box.left, y: event.clientY - box.top};
  }

  function handleAt(position) {
    let best = -1;
    let bestDistance = 12;
    state.points.forEach((p, index) => {
      if (!inView(p)) return;
      const d = Math.hypot(toCanvasX(p.x) - position.x, toCanvasY(p.y) - position.y);
      if (d < bestDistance) {
        best = index;
        bestDistance = d;
      }
    });
    return best;
  }

  function dragTo(position, fine) {
    const snap = fine ? (v) => Math.round(v * 256) / 256 : (v) => Math.round(v);
    const clamp = (v, lo, hi) => Math.min(hi, Math.max(lo, v));
    const x = clamp(snap(fromCanvasX(position.x)), -MARGIN, state.width - 1 + MARGIN);
    const y = clamp(snap(fromCanvasY(position.y)), -MARGIN, state.height - 1 + MARGIN);
    const point = state.points[dragging];
    if (point.x !== x || point.y !== y) setPoint(dragging, x, y);
  }

  function describePixel(position) {
    const i = Math.round(fromCanvasX(position.x));
    const j = Math.round(fromCanvasY(position.y));
    if (i < 0 || j < 0 || i >= state.width || j >= state.height) return '\u00a0';
    const x = fromCanvasX(position.x).toFixed(2);
    const y = fromCanvasY(position.y).toFixed(2);
    let text = `pixel (${i}, ${j}), pointer at (${x}, ${y})`;
    const r = state.result;
    const k = j * state.width + i;
    if (r && r.area) {
      text += `: ${state.algorithm} covers ${(r.coverage[k] / UNIT).toFixed(4)} ` +
              `(${r.coverage[k]}/65535), the exact area ${(r.exact[k] / UNIT).toFixed(4)} ` +
              `(${r.exact[k]}/65535)`;
    } else if (r) {
      text += `: ${state.algorithm} writes it ${r.counts[k]}\u00d7, the oracle ` +
              `${r.oracleCounts[k]}\u00d7`;
    }
    return text;
  }

  for (const view of views) {
    const canvas = view.canvas;
    canvas.addEventListener('pointerdown', (event) => {
      const index = handleAt(pointerPosition(canvas, event));
      if (index < 0) return;
      event.preventDefault();
      canvas.focus();
      state.selected = index;
      dragging = index;
      canvas.setPointerCapture(event.pointerId);
      refreshVertexTable();
      render();
    });
    canvas.addEventListener('pointermove', (event) => {
      const position = pointerPosition(canvas, event);
      hovered = position;
      $('pg-hover').textContent = describePixel(position);
      if (dragging !== null) dragTo(position, event.shiftKey);
    });
    const stop = () => {
      dragging = null;
    };
    canvas.addEventListener('pointerup', stop);
    canvas.addEventListener('pointercancel', stop);
    canvas.addEventListener('keydown', (event) => {
      const moves = {ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1]};
      const move = moves[event.key];
      if (!move) return;
      event.preventDefault();
      const step = event.shiftKey ? SUBPIXEL : 1;
      nudge(state.selected, move[0] * step, move[1] * step);
    });
  }

  // ---- start -----------------------------------------------------------------------------------

  let library = null;

  function start(module) {
    library = new Library(module);
    const select = $('pg-algorithm');
    for (const a of library.algorithms) {
      const option = document.createElement('option');
      option.value = a.name;
      const chapter = a.chapter.slice(0, 2);
      option.textContent = `${a.name} \u2014 chapter ${chapter}, rule ${a.rule}` +
          (a.threaded ? ' (threaded: one thread here)' : '');
      select.appendChild(option);
    }
    const presetSelect = $('pg-preset');
    PRESETS.forEach((preset, index) => {
      const option = document.createElement('option');
      option.value = String(index);
      option.textContent = preset.title;
      presetSelect.appendChild(option);
    });
    const describeAlgorithm = () => {
      const a = selectedAlgorithm();
      $('pg-summary').textContent = `${a.name} (chapters/${a.chapter}, rule ${a.rule}): ` +
          a.summary + (a.threaded ? '. In the browser it draws on one thread: a page without ' +
          'cross-origin isolation cannot start threads, and the library then draws every ' +
          'band itself.' : '.');
      $('pg-caption-algorithm').textContent = a.name;
      $('pg-caption-oracle').textContent = a.rule === 'area' ?
          'chapter 09\'s exact area (the truth)' : 'chapter 07\'s oracle (the exact pixels)';
    };
    state.algorithm = library.algorithms[0].name;
    select.value = state.algorithm;
    select.addEventListener('change', () => {
      state.algorithm = select.value;
      chooseStepList();
      describeAlgorithm();
      update();
    });
    presetSelect.addEventListener('change', () => loadPreset(Number(presetSelect.value)));
    const stepSelect = $('pg-step');
    stepSelect.addEventListener('change', () => {
      state.step = Number(stepSelect.value);
      update();
    });
    for (const id of ['pg-width', 'pg-height']) $(id).addEventListener('input', update);
    window.addEventListener('resize', render);
    for (const id of ['pg-algorithm', 'pg-preset', 'pg-width', 'pg-height']) {
      $(id).disabled = false;
    }
    chooseStepList();
    describeAlgorithm();
    const area = library.algorithms.filter((a) => a.rule === 'area').length;
    status.textContent = `The registry's ${library.algorithms.length - area} triangle ` +
        `algorithms and ${area} coverage algorithms, compiled to WebAssembly from the ` +
        'chapters\' C++, beside chapter 07\'s oracle and chapter 09\'s exact area.';
    loadPreset(0);
  }

  // What a test (tools/playground/test_playground.py) reads: the page's own numbers.
  window.playground = {
    ready: createPlaygroundModule().then((module) => {
      start(module);
      return true;
    }, (error) => {
      status.classList.add('pg-unavailable');
      status.textContent = `The playground's WebAssembly module failed to start: ${error}`;
      throw error;
    }),
    state: () => ({
      algorithm: state.algorithm,
      algorithms: library ? library.algorithms : [],
      width: state.width,
      height: state.height,
      points: state.points.map((p) => ({x: p.x, y: p.y, textX: p.textX, textY: p.textY})),
      triangles: state.triangles,
      error: state.error,
      drawn: state.result !== null,
      counts: state.result && !state.result.area ? Array.from(state.result.counts) : null,
      oracleCounts: state.result && !state.result.area ?
          Array.from(state.result.oracleCounts) : null,
      coverage: state.result && state.result.area ? Array.from(state.result.coverage) : null,
      exact: state.result && state.result.area ? Array.from(state.result.exact) : null,
      steps: state.steps,
      step: state.step,
      stepPixels: state.stepPixels ? Array.from(state.stepPixels) : null,
      scene: $('pg-scene').textContent,
      command: $('pg-command').textContent,
    }),
    // Where vertex `index` is drawn on a view, in the window's coordinates.
    handlePosition: (index, kind) => {
      const canvas = views.find((view) => view.kind === (kind || 'algorithm')).canvas;
      const box = canvas.getBoundingClientRect();
      const p = state.points[index];
      return {x: box.left + toCanvasX(p.x), y: box.top + toCanvasY(p.y), cell};
    },
  };
})();
