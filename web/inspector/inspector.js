// The bsc inspector: draws a chart from a trace's dictionary and replays the trace's records on
// it, live from a program (GET /info, GET /trace?from=N, POST /command) or from a recorded file.
//
// A classic script, as trace.js (loaded before it, into the global BscTrace), so that the page
// also works opened from disk; the function keeps its names out of the global scope.
(function () {
  'use strict';

  const { TraceReader, TraceState, RecordType, StateKind, NONE } = globalThis.BscTrace;

  const POLL_MS = 150;
  const CHECKPOINT = 256; // records between saved states, so that seeking replays at most this many
  const MAX_RECORDS = 200000; // a long live run keeps only its newest records...
  const TRIM = CHECKPOINT * 100; // ...dropping this many at a time (a multiple of CHECKPOINT)
  const LOG_LINES = 1000;
  const FLASH_MS = 1500;
  const SVG = 'http://www.w3.org/2000/svg';
  const NAME_FONT = '600 13px system-ui, "DejaVu Sans", sans-serif';
  const SMALL_FONT = '11px system-ui, "DejaVu Sans", sans-serif';

  const $ = (id) => document.getElementById(id);

  // One trace stream: a machine's, or one actor's of a system.
  function newStream(actor = -1) {
    return {
      actor, // the actor's place in the system's order; -1 for a machine
      reader: new TraceReader(),
      records: [], // the records read, each with its describe() text as `text`
      dropped: 0, // records trimmed off the front in a long live run
      checkpoints: [new TraceState()], // checkpoints[k]: the state before records[k * CHECKPOINT]
      head: new TraceState(), // the state after every record read
      position: -1, // the index of the last record shown
      following: true, // whether new records move the position to the newest
      offset: 0, // live: the byte offset of the next /trace request
      log: { from: 0, to: -1 }, // the absolute record indices the log shows
    };
  }

  const app = {
    mode: null, // 'live' or 'replay'
    info: null, // the program's /info
    system: null, // a system's description ({actors, links}), or null for a machine
    streams: [newStream()], // a system's: one per actor (null for an actor without a tracer)
    stream: null, // the stream shown: the machine's, or the selected actor's
    ready: false,
    zoom: 'fit', // 'fit' or a scale
    scale: 1, // the scale shown
    chart: null, // the drawn chart: {states: Map(n -> g), edges: Map(row -> g[]), internal: Map(row -> el[])}
    chartSignature: '', // the dictionary the drawing shows
    layoutRunning: false,
    layoutAgain: false,
    systemSize: null, // the system's drawing and its size at full scale
  };
  app.stream = app.streams[0];
  // The panes show the stream selected: app.records and the like are its.
  for (const field of ['reader', 'records', 'dropped', 'checkpoints', 'head', 'position', 'following', 'offset', 'log']) {
    Object.defineProperty(app, field, {
      get: () => app.stream[field],
      set: (value) => {
        app.stream[field] = value;
      },
    });
  }

  // ---- Reading records ------------------------------------------------------------------------

  function resetStream(s) {
    Object.assign(s, newStream(s.actor));
  }

  function resetTrace(s = app.stream) {
    resetStream(s);
    if (app.system) updateActor(s);
    if (s !== app.stream) return;
    $('log').replaceChildren();
    scheduleLayout();
    renderMembersTable();
    renderEventButtons();
  }

  /** Feeds bytes of stream s's trace and, if it is the one shown, shows what they add. */
  function ingest(bytes, s = app.stream) {
    const reader = s.reader;
    reader.feed(bytes);
    let layout = false;
    let events = false;
    let members = false;
    const fired = [];
    const first = s.records.length;
    for (let r; (r = reader.next()); ) {
      r.text = reader.describe(r);
      if (s.records.length > 0 && s.records.length % CHECKPOINT === 0) s.checkpoints.push(s.head.clone());
      s.records.push(r);
      s.head.apply(r);
      switch (r.type) {
        case RecordType.hello:
          layout = events = members = true;
          break;
        case RecordType.state:
        case RecordType.row:
          layout = true;
          break;
        case RecordType.event:
          events = true;
          break;
        case RecordType.member:
          members = true;
          break;
        case RecordType.transition:
          fired.push(r.row);
          break;
        default:
          break;
      }
    }
    const added = s.records.length - first;
    trim(s);
    if (app.system && app.stream.following) {
      updateActor(s);
      if (app.mode === 'live' && fired.length > 0) pulseActor(s.actor);
    }
    if (s !== app.stream) return;
    if (layout) scheduleLayout();
    if (events) renderEventButtons();
    if (members) renderMembersTable();
    if (app.following && added > 0) {
      show(app.records.length - 1);
      if (app.mode === 'live') flash(fired);
    } else {
      updateTimeline();
    }
    updateCounters();
  }

  // Drops the oldest records of a long run, keeping the state before the first one kept.
  function trim(s) {
    while (s.records.length > MAX_RECORDS) {
      s.records.splice(0, TRIM);
      s.checkpoints.splice(0, TRIM / CHECKPOINT);
      s.dropped += TRIM;
      s.position = Math.max(s.position - TRIM, 0);
    }
  }

  /** The state after records[0..pos]. */
  function stateAt(pos, stream = app.stream) {
    if (pos === stream.records.length - 1) return stream.head;
    if (pos < 0) return stream.checkpoints[0];
    const k = Math.floor(pos / CHECKPOINT);
    const s = stream.checkpoints[k].clone();
    for (let i = k * CHECKPOINT; i <= pos; ++i) s.apply(stream.records[i]);
    return s;
  }

  // ---- Showing a position ---------------------------------------------------------------------

  /** Shows the configuration, values, fired transitions and log up to records[pos]. */
  function show(pos) {
    const last = app.records.length - 1;
    app.position = Math.max(Math.min(pos, last), last >= 0 ? 0 : -1);
    const s = stateAt(app.position);
    renderActive(s);
    renderValues(s);
    renderLog();
    updateTimeline();
    if (app.system) syncActors();
  }

  function renderActive(s) {
    if (!app.chart) return;
    for (const [n, g] of app.chart.states) g.classList.toggle('active', s.active.has(n));
    const fired = new Set(s.fired);
    const rows = app.reader.dictionary.rows;
    // The transitions out of active states are the ones that can fire next: the others are dimmed.
    app.chart.svg.classList.toggle('has-active', s.active.size > 0);
    for (const [row, els] of app.chart.edges) {
      for (const el of els) {
        el.classList.toggle('fired', fired.has(row));
        el.classList.toggle('enabled', s.active.has(rows[row]?.source));
      }
    }
    for (const [row, els] of app.chart.internal) for (const el of els) el.classList.toggle('fired', fired.has(row));
  }

  // Live: the transitions just read pulse for a moment, however soon the next step clears them.
  const flashTimers = new Map();
  function flash(rows) {
    if (!app.chart) return;
    for (const row of new Set(rows)) {
      const els = [...(app.chart.edges.get(row) ?? []), ...(app.chart.internal.get(row) ?? [])];
      for (const el of els) {
        el.classList.remove('flash');
        void el.getBoundingClientRect(); // restarts the animation of an element flashed just before
        el.classList.add('flash');
      }
      clearTimeout(flashTimers.get(row));
      flashTimers.set(row, setTimeout(() => els.forEach((el) => el.classList.remove('flash')), FLASH_MS));
    }
  }

  function activeNames() {
    const s = stateAt(app.position);
    const d = app.reader.dictionary;
    return [...s.active].sort((a, b) => a - b).map((n) => d.stateName(n));
  }

  // ---- Members --------------------------------------------------------------------------------

  function renderMembersTable() {
    const d = app.reader.dictionary;
    const body = $('members').tBodies[0];
    const rows = [];
    const select = $('set-member');
    const selected = select.value;
    const options = [];
    d.members.forEach((m, n) => {
      if (!m.name) return;
      const tr = document.createElement('tr');
      tr.dataset.member = m.name;
      tr.dataset.number = String(n);
      const name = document.createElement('td');
      name.className = 'name';
      name.textContent = m.name;
      name.title = ['bool', 'signed', 'unsigned', 'real'][m.kind] ?? `kind ${m.kind}`;
      const value = document.createElement('td');
      value.className = 'value';
      tr.append(name, value);
      rows.push(tr);
      const option = document.createElement('option');
      option.value = option.textContent = m.name;
      options.push(option);
    });
    body.replaceChildren(...rows);
    select.replaceChildren(...options);
    if (selected) select.value = selected;
    $('no-members').hidden = rows.length > 0;
    renderValues(stateAt(app.position), false);
  }

  function renderValues(s, mark = true) {
    const d = app.reader.dictionary;
    for (const tr of $('members').tBodies[0].rows) {
      const n = Number(tr.dataset.number);
      const bits = s.values.get(n);
      const text = bits === undefined ? '' : d.valueText(n, bits);
      const cell = tr.cells[1];
      if (cell.textContent === text) continue;
      cell.textContent = text;
      if (mark && app.following && app.mode === 'live') {
        tr.classList.remove('changed');
        void tr.offsetWidth;
        tr.classList.add('changed');
      }
    }
  }

  // ---- The log --------------------------------------------------------------------------------

  function logLine(r, index) {
    const div = document.createElement('div');
    div.className = `line ${r.typeName}`;
    if (r.type === RecordType.cycle || r.type === RecordType.cycleEnd) div.classList.add('cycle');
    div.dataset.index = String(index);
    div.textContent = r.text;
    return div;
  }

  // Shows the last LOG_LINES records up to the position, appending where it can instead of
  // rebuilding, and scrolls to the newest unless the reader has scrolled up while following.
  function renderLog() {
    const log = $('log');
    const end = app.dropped + app.position; // absolute index of the last line
    const from = Math.max(app.dropped, end - LOG_LINES + 1);
    const stick = !app.following || log.scrollHeight - log.scrollTop - log.clientHeight < 40;
    if (end >= app.log.to && app.log.from <= from && from <= app.log.to + 1 && app.log.to >= app.log.from) {
      const fragment = document.createDocumentFragment();
      for (let i = app.log.to + 1; i <= end; ++i) fragment.append(logLine(app.records[i - app.dropped], i));
      log.append(fragment);
      while (log.firstChild && Number(log.firstChild.dataset.index) < from) log.firstChild.remove();
    } else {
      const lines = [];
      for (let i = from; i <= end; ++i) lines.push(logLine(app.records[i - app.dropped], i));
      log.replaceChildren(...lines);
    }
    app.log = { from, to: end };
    log.querySelector('.current')?.classList.remove('current');
    if (!app.following) log.lastElementChild?.classList.add('current');
    if (stick) log.scrollTop = log.scrollHeight;
  }

  // ---- The timeline ---------------------------------------------------------------------------

  function updateTimeline() {
    const range = $('timeline');
    const count = app.records.length;
    range.max = String(Math.max(count - 1, 0));
    range.value = String(Math.max(app.position, 0));
    range.disabled = count === 0;
    const r = app.records[app.position];
    const time = r ? r.text.slice(0, r.text.indexOf(']') + 1) : '';
    $('timeline-label').textContent = count
      ? `record ${app.position + 1} of ${count} ${time}${app.following ? '' : ' · paused view'}`
      : 'no records yet';
    $('live').classList.toggle('on', app.following);
    $('step-back').disabled = app.position <= 0;
    $('step-forward').disabled = app.position >= count - 1;
  }

  function seek(pos) {
    app.following = false;
    show(pos);
  }

  function follow() {
    app.following = true;
    show(app.records.length - 1);
  }

  // ---- Drawing the chart ----------------------------------------------------------------------

  const measure = (() => {
    const context = document.createElement('canvas').getContext('2d');
    return (text, font) => {
      context.font = font;
      return Math.ceil(context.measureText(text).width);
    };
  })();

  // The chart's structure from the dictionary: the states to draw (all but the implicit top),
  // each one's parent among them, and the rows as edges or as internal lines. A malformed
  // dictionary (a parent loop, a missing state) still gives a tree.
  function structure(d) {
    const drawn = new Set();
    d.states.forEach((s, n) => {
      if (s && s.kind !== StateKind.top) drawn.add(n);
    });
    const parent = new Map();
    for (const n of drawn) {
      const p = d.states[n].parent;
      parent.set(n, p !== n && drawn.has(p) ? p : null);
    }
    // Cut any loop: a state whose chain of parents does not reach the top within the number of
    // states is made a top-level one.
    for (const n of drawn) {
      let p = parent.get(n);
      for (let steps = 0; p !== null && steps <= drawn.size; ++steps) p = parent.get(p);
      if (p !== null) parent.set(n, null);
    }
    const children = new Map([...drawn].map((n) => [n, []]));
    const tops = [];
    for (const n of drawn) (parent.get(n) === null ? tops : children.get(parent.get(n))).push(n);
    const edges = [];
    const internal = new Map([...drawn].map((n) => [n, []]));
    d.rows.forEach((row, number) => {
      if (!row || !drawn.has(row.source)) return;
      if (row.target === NONE) internal.get(row.source).push({ number, row });
      else if (drawn.has(row.target)) edges.push({ number, row });
    });
    const ancestors = (n) => {
      const chain = [];
      for (let p = parent.get(n); p !== null && p !== undefined; p = parent.get(p)) chain.push(p);
      return chain;
    };
    return { drawn, parent, children, tops, edges, internal, ancestors };
  }

  const rowText = (row) => (row.label || '(unnamed)') + (row.flags & 1 ? ' (defers)' : '');

  // Spacing is read from each node holding children, not only from the root.
  const spacing = {
    'elk.edgeLabels.placement': 'CENTER',
    'elk.spacing.nodeNode': '16',
    'elk.layered.spacing.nodeNodeBetweenLayers': '24',
    'elk.spacing.edgeEdge': '5',
    'elk.layered.spacing.edgeEdgeBetweenLayers': '5',
    'elk.spacing.edgeLabel': '2',
    'elk.spacing.edgeNode': '9',
    'elk.layered.spacing.edgeNodeBetweenLayers': '9',
  };

  // The ELK graph: containers get room at the top for their name and internal rows.
  function elkGraph(d, st, edgeFilter) {
    const node = (n) => {
      const s = d.states[n];
      const name = s.name || `#${n}`;
      const lines = st.internal.get(n).map(({ row }) => rowText(row));
      const textWidth = Math.max(measure(name, NAME_FONT), ...lines.map((l) => measure(l, SMALL_FONT)));
      const kids = st.children.get(n);
      const g = { id: `s${n}`, layoutOptions: { ...spacing, ...(globalThis.bscLayoutOptions ?? {}) } };
      if (kids.length) {
        g.children = kids.map(node);
        g.layoutOptions['elk.padding'] = `[top=${30 + lines.length * 15},left=14,bottom=14,right=14]`;
        g.layoutOptions['elk.nodeSize.constraints'] = 'MINIMUM_SIZE';
        g.layoutOptions['elk.nodeSize.minimum'] = `(${textWidth + 28}, ${40 + lines.length * 15})`;
      } else if (s.kind === StateKind.history) {
        g.width = g.height = 28;
      } else {
        g.width = Math.max(textWidth + 28, 64);
        g.height = 32 + lines.length * 15;
      }
      return g;
    };
    const graph = {
      id: 'root',
      layoutOptions: {
        ...spacing,
        'elk.algorithm': 'layered',
        'elk.hierarchyHandling': 'INCLUDE_CHILDREN',
        'elk.direction': 'RIGHT',
        'elk.json.edgeCoords': 'ROOT',
        'elk.json.shapeCoords': 'ROOT',
        'elk.edgeRouting': 'ORTHOGONAL',
        'elk.padding': '[top=8,left=8,bottom=8,right=8]',
        ...(globalThis.bscLayoutOptions ?? {}),
      },
      children: st.tops.map(node),
      edges: [],
    };
    // Each edge lives in the innermost container holding both ends, as ELK expects.
    const byId = new Map();
    const index = (g) => {
      byId.set(g.id, g);
      (g.children ?? []).forEach(index);
    };
    index(graph);
    for (const { number, row } of st.edges) {
      if (!edgeFilter(row)) continue;
      const a = [row.source, ...st.ancestors(row.source)];
      const b = new Set([row.target, ...st.ancestors(row.target)]);
      let lca = a.find((n) => b.has(n));
      // Between a state and itself or its descendant the edge belongs to the state's parent.
      if (lca === row.source || lca === row.target) lca = st.parent.get(lca);
      const container = lca === null || lca === undefined ? graph : byId.get(`s${lca}`);
      container.edges ??= [];
      const text = rowText(row);
      container.edges.push({
        id: `r${number}`,
        sources: [`s${row.source}`],
        targets: [`s${row.target}`],
        labels: [{ text, width: measure(text, SMALL_FONT) + 6, height: 14 }],
      });
    }
    return graph;
  }

  // Without ELK (elk.bundled.js missing, or every layout failed): nested boxes in wrapped rows,
  // no edges, so that the configuration still shows.
  function plainLayout(d, st) {
    const place = (n) => {
      const s = d.states[n];
      const name = s.name || `#${n}`;
      const lines = st.internal.get(n).map(({ row }) => rowText(row));
      const textWidth = Math.max(measure(name, NAME_FONT), ...lines.map((l) => measure(l, SMALL_FONT)));
      const kids = st.children.get(n).map(place);
      if (!kids.length) return { id: `s${n}`, x: 0, y: 0, width: Math.max(textWidth + 28, 64), height: 32 + lines.length * 15 };
      const top = 30 + lines.length * 15;
      let x = 14;
      let y = top;
      let rowHeight = 0;
      let width = textWidth + 28;
      for (const k of kids) {
        if (x > 14 && x + k.width > 640) {
          x = 14;
          y += rowHeight + 16;
          rowHeight = 0;
        }
        k.x = x;
        k.y = y;
        x += k.width + 16;
        rowHeight = Math.max(rowHeight, k.height);
        width = Math.max(width, x - 2);
      }
      return { id: `s${n}`, x: 0, y: 0, width, height: y + rowHeight + 14, children: kids };
    };
    const tops = st.tops.map(place);
    let y = 8;
    let width = 0;
    for (const t of tops) {
      t.x = 8;
      t.y = y;
      y += t.height + 16;
      width = Math.max(width, t.width + 16);
    }
    // Children were placed relative to their parent: make every position absolute, as ELK's ROOT coordinates.
    const absolute = (g, dx, dy) => {
      g.x += dx;
      g.y += dy;
      (g.children ?? []).forEach((c) => absolute(c, g.x, g.y));
    };
    tops.forEach((t) => absolute(t, 0, 0));
    return { id: 'root', width, height: y, children: tops, edges: [] };
  }

  function scheduleLayout() {
    if (app.layoutRunning) {
      app.layoutAgain = true;
      return;
    }
    app.layoutRunning = true;
    // Let a burst of dictionary records finish before laying out.
    setTimeout(async () => {
      try {
        do {
          app.layoutAgain = false;
          await layoutChart();
        } while (app.layoutAgain);
      } finally {
        app.layoutRunning = false;
      }
    }, 0);
  }

  async function layoutChart() {
    const d = app.reader.dictionary;
    const actor = app.system && app.stream.actor >= 0 ? app.system.actors[app.stream.actor].name : '';
    const title = actor ? `${actor} · ${d.chart}` : d.chart;
    $('chart-name').textContent = title;
    document.title = title ? `${title} · bsc inspector` : 'bsc inspector';
    // A dictionary written again (for late readers) mostly names the same chart: keep the drawing.
    const signature = JSON.stringify([d.states, d.rows]);
    if (app.chart && signature === app.chartSignature) return;
    const st = structure(d);
    if (st.drawn.size === 0) {
      app.chart = null;
      $('chart').replaceChildren(placeholder('Waiting for the trace\u2019s dictionary…'));
      return;
    }
    let laid = null;
    let note = '';
    if (typeof ELK === 'function') {
      const elk = new ELK();
      const isAncestor = (a, b) => st.ancestors(b).includes(a);
      // Hierarchy-crossing edges between a state and its own descendant are the likeliest to
      // trouble the layout: without them, and then without edges, before giving up.
      const attempts = [
        [() => true, ''],
        [(row) => !isAncestor(row.source, row.target) && !isAncestor(row.target, row.source), 'some transitions not drawn'],
        [() => false, 'transitions not drawn'],
      ];
      for (const [filter, why] of attempts) {
        try {
          laid = await elk.layout(elkGraph(d, st, filter));
          note = why;
          break;
        } catch (e) {
          console.warn('layout failed:', e);
        }
      }
    } else {
      note = 'elk.bundled.js is missing: transitions not drawn';
    }
    if (!laid) {
      laid = plainLayout(d, st);
      note ||= 'layout failed: transitions not drawn';
    }
    if (d !== app.reader.dictionary) return; // a hello started a new dictionary meanwhile
    render(d, st, laid);
    app.chartSignature = signature;
    if (note) setStatus(note, 'error');
    app.ready = true;
    show(app.position);
  }

  function placeholder(text) {
    const p = document.createElement('p');
    p.className = 'placeholder';
    p.textContent = text;
    return p;
  }

  function el(name, attributes = {}, text) {
    const e = document.createElementNS(SVG, name);
    for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, String(v));
    if (text !== undefined) e.textContent = text;
    return e;
  }

  function render(d, st, laid) {
    const width = Math.ceil(laid.width ?? 0);
    const height = Math.ceil(laid.height ?? 0);
    const svg = el('svg', { id: 'chart-svg', viewBox: `0 0 ${width} ${height}`, width, height });
    const chart = { svg, width, height, states: new Map(), edges: new Map(), internal: new Map() };
    const defs = el('defs');
    for (const [id, cls] of [['arrow', 'arrow'], ['arrow-fired', 'arrow fired']]) {
      const marker = el('marker', { id, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse' });
      marker.append(el('path', { d: 'M0,0 L10,5 L0,10 z', class: cls }));
      defs.append(marker);
    }
    svg.append(defs);
    const states = el('g', { class: 'states' });
    const edges = el('g', { class: 'edges' });
    svg.append(states, edges);

    const addInternal = (row, element) => {
      if (!chart.internal.has(row)) chart.internal.set(row, []);
      chart.internal.get(row).push(element);
    };
    // Parents before children, so that children paint on top.
    const drawNode = (g) => {
      const n = Number(g.id.slice(1));
      const s = d.states[n];
      const name = s.name || `#${n}`;
      const container = (g.children ?? []).length > 0;
      const parentKind = st.parent.get(n) === null ? null : d.states[st.parent.get(n)].kind;
      const kindName = Object.keys(StateKind).find((k) => StateKind[k] === s.kind) ?? 'basic';
      const group = el('g', { class: `state kind-${kindName}${container ? ' container' : ''}${parentKind === StateKind.parallel ? ' region' : ''}` });
      group.dataset.state = name;
      group.dataset.number = String(n);
      group.append(el('title', {}, `${name} (${kindName})`));
      const { x, y, width: w, height: h } = g;
      if (s.kind === StateKind.history && !container) {
        group.append(el('circle', { cx: x + w / 2, cy: y + h / 2, r: w / 2, class: 'shape' }));
        group.append(el('text', { x: x + w / 2, y: y + h / 2 + 4, class: 'name history', 'text-anchor': 'middle' }, 'H'));
      } else {
        group.append(el('rect', { x, y, width: w, height: h, rx: container ? 10 : 8, class: 'shape' }));
        if (s.kind === StateKind.final) group.append(el('rect', { x: x + 3, y: y + 3, width: w - 6, height: h - 6, rx: 6, class: 'inner' }));
        const lines = st.internal.get(n);
        if (container) {
          group.append(el('text', { x: x + 12, y: y + 19, class: 'name' }, name));
          if (s.kind === StateKind.parallel) group.append(el('text', { x: x + w - 12, y: y + 19, class: 'kind-mark', 'text-anchor': 'end' }, 'parallel'));
          lines.forEach(({ number, row }, i) => {
            const t = el('text', { x: x + 12, y: y + 34 + i * 15, class: 'internal' }, rowText(row));
            t.dataset.row = String(number);
            group.append(t);
            addInternal(number, t);
          });
          if (lines.length) group.append(el('line', { x1: x, x2: x + w, y1: y + 26 + lines.length * 15, y2: y + 26 + lines.length * 15, class: 'divider' }));
          else group.append(el('line', { x1: x, x2: x + w, y1: y + 26, y2: y + 26, class: 'divider' }));
        } else {
          group.append(el('text', { x: x + w / 2, y: y + 20, class: 'name', 'text-anchor': 'middle' }, name));
          lines.forEach(({ number, row }, i) => {
            const t = el('text', { x: x + w / 2, y: y + 35 + i * 15, class: 'internal', 'text-anchor': 'middle' }, rowText(row));
            t.dataset.row = String(number);
            group.append(t);
            addInternal(number, t);
          });
        }
      }
      states.append(group);
      chart.states.set(n, group);
      (g.children ?? []).forEach(drawNode);
    };
    (laid.children ?? []).forEach(drawNode);

    const drawEdges = (g) => {
      for (const e of g.edges ?? []) {
        const row = Number(e.id.slice(1));
        const group = el('g', { class: 'edge' });
        group.dataset.row = String(row);
        for (const section of e.sections ?? []) {
          const points = [section.startPoint, ...(section.bendPoints ?? []), section.endPoint];
          group.append(el('path', { d: points.map((p, i) => `${i ? 'L' : 'M'}${p.x},${p.y}`).join(' '), class: 'line' }));
        }
        for (const label of e.labels ?? []) {
          group.append(el('rect', { x: label.x, y: label.y, width: label.width, height: label.height, rx: 3, class: 'label-back' }));
          group.append(el('text', { x: label.x + 3, y: label.y + label.height - 3, class: 'label' }, label.text));
        }
        group.append(el('title', {}, `row ${row}: ${d.stateName(d.rows[row].source)} -> ${d.stateName(d.rows[row].target)} : ${rowText(d.rows[row])}`));
        edges.append(group);
        if (!chart.edges.has(row)) chart.edges.set(row, []);
        chart.edges.get(row).push(group);
      }
      (g.children ?? []).forEach(drawEdges);
    };
    drawEdges(laid);

    $('chart').replaceChildren(svg);
    app.chart = chart;
    applyZoom();
  }

  // ---- Zoom -----------------------------------------------------------------------------------

  // 'fit' scales the chart down to the pane (never up); a number is a fixed scale.
  function applyZoom() {
    const chart = app.chart;
    if (!chart) return;
    const pane = $('chart');
    let scale = app.zoom;
    if (scale === 'fit') scale = Math.min(1, (pane.clientWidth - 4) / chart.width, (pane.clientHeight - 4) / chart.height);
    scale = Math.max(scale, 0.05);
    app.scale = scale;
    chart.svg.setAttribute('width', String(Math.round(chart.width * scale)));
    chart.svg.setAttribute('height', String(Math.round(chart.height * scale)));
    $('zoom-level').textContent = `${Math.round(scale * 100)}%`;
    $('zoom-fit').classList.toggle('on', app.zoom === 'fit');
  }

  function zoom(factor) {
    app.zoom = Math.min(4, Math.max(0.1, (app.scale ?? 1) * factor));
    applyZoom();
  }

  // ---- Commands -------------------------------------------------------------------------------

  function setStatus(text, kind = '') {
    const status = $('status');
    status.textContent = text;
    status.className = `status ${kind}`;
  }

  async function command(text) {
    setStatus(`${text}…`);
    try {
      // The custom header makes a browser ask the server before another site's page could send it.
      const response = await fetch('/command', { method: 'POST', headers: { 'Content-Type': 'text/plain', 'X-Bsc-Command': '1' }, body: text });
      const body = (await response.text()).trim();
      if (response.ok) setStatus(body || 'ok', 'ok');
      else setStatus(`${text}: ${response.status} ${body || response.statusText}`, 'error');
    } catch (e) {
      setStatus(`${text}: ${e.message}`, 'error');
    }
    if (/^(pause|resume|step)\b/.test(text)) await refreshInfo();
    pollNow();
  }

  const hiddenEvent = (name) => !name || name.startsWith('done.state.') || name.startsWith('error.') || name.startsWith('*');

  function renderEventButtons() {
    const buttons = [];
    for (const name of app.reader.dictionary.events) {
      if (hiddenEvent(name)) continue;
      const button = document.createElement('button');
      button.type = 'button';
      button.dataset.event = name;
      button.textContent = name;
      button.title = `dispatch ${name}`;
      button.addEventListener('click', () => command(`dispatch ${actorWord()}${name}`));
      buttons.push(button);
    }
    $('events').replaceChildren(...buttons);
  }

  function renderControls() {
    const info = app.info;
    const commands = app.mode === 'live' && info && info.commands === true;
    $('controls').hidden = !commands;
    $('scan-controls').hidden = !(commands && info.scan === true);
    const readOnly = $('read-only');
    readOnly.hidden = commands;
    readOnly.textContent =
      app.mode === 'live'
        ? 'Read-only view: the program does not take commands (start it with --commands).'
        : 'Read-only view: replaying a recorded trace.';
    const runState = $('run-state');
    runState.hidden = !(app.mode === 'live' && info && info.scan === true);
    runState.textContent = info && info.paused ? 'paused' : 'running';
    runState.classList.toggle('paused', !!(info && info.paused));
  }

  // ---- Live mode ------------------------------------------------------------------------------

  async function fetchInfo() {
    const response = await fetch('/info', { cache: 'no-store' });
    if (!response.ok) throw new Error(`/info: HTTP ${response.status}`);
    const info = await response.json();
    if (!info || typeof info !== 'object') throw new Error('/info: not an object');
    return info;
  }

  async function refreshInfo() {
    try {
      app.info = await fetchInfo();
      renderControls();
    } catch {
      // The next poll reports a lost connection.
    }
  }

  let polling = false;
  let pollTimer = 0;
  let failures = 0;

  function pollNow() {
    if (app.mode !== 'live' || polling) return;
    clearTimeout(pollTimer);
    poll();
  }

  // Reads what is new in stream s's trace: a machine's, or an actor's of a system.
  async function pollStream(s) {
    const actor = s.actor >= 0 ? `actor=${s.actor}&` : '';
    const response = await fetch(`/trace?${actor}from=${s.offset}`, { cache: 'no-store' });
    if (!response.ok) throw new Error(`HTTP ${response.status}`);
    const body = new Uint8Array(await response.arrayBuffer());
    const number = (name) => {
      const text = (response.headers.get(name) ?? '').trim();
      return /^\d+$/.test(text) ? Number(text) : null;
    };
    const end = number('X-Trace-End') ?? s.offset + body.length;
    const start = number('X-Trace-Start') ?? end - body.length;
    // The program keeps a bounded history: bytes it let go before this page read them are lost.
    if (start > s.offset && s.offset > 0) setStatus(`the program let go of ${start - s.offset} trace bytes before they were read`, 'error');
    if (end < s.offset) {
      // The program's trace is shorter than what was read: a new run; read it from the start.
      resetTrace(s);
      s.offset = 0;
    } else {
      s.offset = end;
      if (body.length) ingest(body, s);
    }
  }

  async function poll() {
    polling = true;
    try {
      // Every stream's request ends before the next poll, also when one of them fails: a stream
      // read twice from one offset would take its bytes twice.
      const results = await Promise.allSettled(app.streams.filter((s) => s !== null).map(pollStream));
      const failed = results.find((r) => r.status === 'rejected');
      if (failed) throw failed.reason;
      if (failures) setStatus('connected again', 'ok');
      failures = 0;
      setConnection('connected', 'ok');
    } catch (e) {
      ++failures;
      setConnection(`no connection (${e.message})`, 'error');
    } finally {
      polling = false;
      pollTimer = setTimeout(poll, failures ? Math.min(POLL_MS * 2 ** failures, 3000) : POLL_MS);
    }
  }

  function setConnection(text, kind) {
    const c = $('connection');
    c.textContent = text;
    c.className = `badge ${kind}`;
    c.hidden = !text;
  }

  // ---- Replay mode ----------------------------------------------------------------------------

  function loadTrace(bytes, name) {
    resetTrace();
    app.reader.finish(); // a file is whole: a frame cut at its end is damage, not bytes to wait for
    ingest(bytes);
    const r = app.reader;
    setStatus(`${name}: ${app.records.length} records`, 'ok');
    if (r.frames === 0) setStatus(`${name}: no trace frames found`, 'error');
  }

  async function loadFile(file) {
    try {
      leaveSystem();
      loadTrace(new Uint8Array(await file.arrayBuffer()), file.name);
    } catch (e) {
      setStatus(`${file.name}: ${e.message}`, 'error');
    }
  }

  // One file: a machine's trace. Several: a system's recording, system.json (its description)
  // and <actor>.bsctrace for each traced actor.
  function loadFiles(list) {
    const files = [...(list ?? [])];
    if (files.length === 1 && !files[0].name.endsWith('.json')) return loadFile(files[0]);
    if (files.length > 0) return loadSystem(files);
    return undefined;
  }

  async function loadSystem(files) {
    const described = files.find((f) => f.name === 'system.json');
    if (!described) {
      setStatus('a system\u2019s recording needs its system.json among the files chosen', 'error');
      return;
    }
    try {
      const info = JSON.parse(await described.text());
      if (!info || info.system !== true || !Array.isArray(info.actors)) throw new Error('not a system\u2019s description');
      leaveSystem();
      startSystem(info);
      let records = 0;
      const missing = [];
      for (const s of app.streams) {
        if (!s) continue;
        const name = app.system.actors[s.actor].name;
        const file = files.find((f) => f.name === `${name}.bsctrace`);
        if (!file) {
          missing.push(name);
          continue;
        }
        s.reader.finish(); // a file is whole: a frame cut at its end is damage
        ingest(new Uint8Array(await file.arrayBuffer()), s);
        records += s.records.length;
      }
      selectActor(app.stream.actor);
      setStatus(
        `system.json: ${app.system.actors.length} actors, ${records} records` + (missing.length ? `; no trace of ${missing.join(', ')}` : ''),
        missing.length ? 'error' : 'ok',
      );
    } catch (e) {
      setStatus(`system.json: ${e.message}`, 'error');
    }
  }

  async function loadUrl(url) {
    setStatus(`loading ${url}…`);
    try {
      const response = await fetch(url, { cache: 'no-store' });
      if (!response.ok) throw new Error(`HTTP ${response.status}`);
      loadTrace(new Uint8Array(await response.arrayBuffer()), url);
    } catch (e) {
      setStatus(`${url}: ${e.message}`, 'error');
    }
  }

  function startReplay() {
    app.mode = 'replay';
    $('mode').textContent = 'replay';
    $('open').hidden = false;
    $('live').textContent = 'end';
    $('live').title = 'Go to the last record';
    setConnection('', '');
    renderControls();
    $('trace-file').addEventListener('change', (e) => loadFiles(e.target.files));
    document.addEventListener('dragover', (e) => e.preventDefault());
    document.addEventListener('drop', (e) => {
      e.preventDefault();
      loadFiles(e.dataTransfer?.files);
    });
  }

  // ---- A system: one box per actor, the links between them ------------------------------------

  const actorWord = () => (app.system && app.stream.actor >= 0 ? `${app.system.actors[app.stream.actor].name} ` : '');
  const actorBox = (i) => document.querySelector(`#system-svg .actor[data-actor="${i}"]`);

  function startSystem(info) {
    const actors = info.actors.map((a) => ({ name: String(a.name ?? ''), chart: String(a.chart ?? ''), traced: a.traced === true }));
    const count = actors.length;
    const links = (Array.isArray(info.links) ? info.links : []).filter(
      (l) => Number.isInteger(l.from) && Number.isInteger(l.to) && l.from >= 0 && l.to >= 0 && l.from < count && l.to < count,
    );
    app.system = { actors, links };
    app.streams = actors.map((a, i) => (a.traced ? newStream(i) : null));
    const first = app.streams.find((s) => s !== null);
    app.stream = first ?? newStream();
    $('system-pane').hidden = false;
    $('system-note').textContent = `${count} actors · ${links.length} links · click an actor to show its chart`;
    layoutSystem();
    if (first) selectActor(first.actor);
  }

  // The links between two actors as one edge: its label names the channels.
  function linkGroups(links, names) {
    const groups = new Map();
    for (const l of links) {
      const key = `${l.from}>${l.to}`;
      if (!groups.has(key)) groups.set(key, { from: l.from, to: l.to, channels: [] });
      const from = String(l.from_channel ?? ''), to = String(l.to_channel ?? '');
      groups.get(key).channels.push({ text: from === to ? from : `${from}→${to}`, title: `${names[l.from]}.${from} → ${names[l.to]}.${to}${l.lossless ? ' (lossless)' : ''}` });
    }
    return [...groups.values()];
  }

  const ACTOR_WIDTH = 200;
  const ACTOR_HEIGHT = 50;
  const LABEL_CHARS = 30;

  async function layoutSystem() {
    const { actors, links } = app.system;
    const names = actors.map((a) => a.name);
    const groups = linkGroups(links, names);
    const label = (g) => {
      const text = g.channels.map((c) => c.text).join(', ');
      return text.length > LABEL_CHARS ? `${text.slice(0, LABEL_CHARS - 1)}…` : text;
    };
    const graph = {
      id: 'system',
      layoutOptions: {
        'elk.algorithm': 'layered',
        'elk.direction': 'RIGHT',
        'elk.spacing.nodeNode': '24',
        'elk.layered.spacing.nodeNodeBetweenLayers': '60',
        'elk.edgeRouting': 'SPLINES',
        'elk.edgeLabels.placement': 'CENTER',
      },
      children: actors.map((a, i) => ({ id: `a${i}`, width: Math.max(ACTOR_WIDTH, measure(a.name, NAME_FONT) + 24), height: ACTOR_HEIGHT })),
      edges: groups.map((g, k) => ({ id: `l${k}`, sources: [`a${g.from}`], targets: [`a${g.to}`], labels: [{ text: label(g), width: measure(label(g), SMALL_FONT) + 6, height: 14 }] })),
    };
    let laid = null;
    if (typeof ELK === 'function') {
      try {
        laid = await new ELK().layout(graph);
      } catch (e) {
        console.warn('system layout failed:', e);
      }
    }
    if (!laid) {
      // Without the layout engine: the actors in rows, the links left out.
      const perRow = 4;
      graph.children.forEach((c, i) => Object.assign(c, { x: 8 + (i % perRow) * (ACTOR_WIDTH + 30), y: 8 + Math.floor(i / perRow) * (ACTOR_HEIGHT + 20) }));
      laid = { ...graph, edges: [], width: 16 + Math.min(actors.length, perRow) * (ACTOR_WIDTH + 30), height: 16 + Math.ceil(actors.length / perRow) * (ACTOR_HEIGHT + 20) };
      $('system-note').textContent += ' · links not drawn (no layout engine)';
    }
    renderSystem(laid, groups);
  }

  function renderSystem(laid, groups) {
    const width = Math.ceil(laid.width ?? 0);
    const height = Math.ceil(laid.height ?? 0);
    const svg = el('svg', { id: 'system-svg', viewBox: `0 0 ${width} ${height}`, width, height });
    const defs = el('defs');
    const marker = el('marker', { id: 'link-arrow', viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse' });
    marker.append(el('path', { d: 'M0,0 L10,5 L0,10 z', class: 'arrow' }));
    defs.append(marker);
    svg.append(defs);
    const edges = el('g', { class: 'links' });
    for (const e of laid.edges ?? []) {
      const g = groups[Number(e.id.slice(1))];
      const group = el('g', { class: 'link' });
      group.dataset.from = String(g.from);
      group.dataset.to = String(g.to);
      group.dataset.channels = g.channels.map((c) => c.text).join(', ');
      for (const section of e.sections ?? []) {
        const points = [section.startPoint, ...(section.bendPoints ?? []), section.endPoint];
        group.append(el('path', { d: points.map((p, i) => `${i ? 'L' : 'M'}${p.x},${p.y}`).join(' '), class: 'line' }));
      }
      for (const l of e.labels ?? []) {
        group.append(el('rect', { x: l.x, y: l.y, width: l.width, height: l.height, rx: 3, class: 'label-back' }));
        group.append(el('text', { x: l.x + 3, y: l.y + l.height - 3, class: 'label' }, l.text));
      }
      group.append(el('title', {}, g.channels.map((c) => c.title).join('\n')));
      edges.append(group);
    }
    const boxes = el('g', { class: 'actors' });
    for (const c of laid.children ?? []) {
      const i = Number(c.id.slice(1));
      const a = app.system.actors[i];
      const group = el('g', { class: `actor${a.traced ? '' : ' untraced'}` });
      group.dataset.actor = String(i);
      group.dataset.name = a.name;
      group.append(el('title', {}, a.traced ? `${a.name}: ${a.chart} (click to show its chart)` : `${a.name}: not traced`));
      group.append(el('rect', { x: c.x, y: c.y, width: c.width, height: c.height, rx: 7, class: 'shape' }));
      group.append(el('text', { x: c.x + 10, y: c.y + 19, class: 'name' }, a.name));
      group.append(el('text', { x: c.x + 10, y: c.y + 38, class: 'states' }, a.traced ? '' : 'not traced'));
      if (a.traced) group.addEventListener('click', () => selectActor(i));
      boxes.append(group);
    }
    svg.append(edges, boxes);
    $('system').replaceChildren(svg);
    app.systemSize = { svg, width, height };
    fitSystem();
    for (const s of app.streams) if (s) updateActor(s);
    markSelected();
  }

  // The diagram scaled down to the pane's width (never up): a wide system stays readable by
  // scrolling down rather than sideways.
  function fitSystem() {
    const size = app.systemSize;
    if (!size) return;
    const scale = Math.max(0.3, Math.min(1, ($('system').clientWidth - 4) / size.width));
    size.svg.setAttribute('width', String(Math.round(size.width * scale)));
    size.svg.setAttribute('height', String(Math.round(size.height * scale)));
  }

  // Back to a single machine's panes (a machine's file opened after a system's).
  function leaveSystem() {
    if (!app.system) return;
    app.system = null;
    app.systemSize = null;
    app.streams = [newStream()];
    app.stream = app.streams[0];
    $('system-pane').hidden = true;
    $('system').replaceChildren();
  }

  // Each box shows its actor where the selected actor's position is: at the time of the record
  // shown (the newest records while following).
  function syncActors() {
    const shown = app.stream;
    if (shown.following) {
      for (const s of app.streams) if (s) updateActor(s);
      return;
    }
    const time = shown.records[shown.position]?.time;
    for (const s of app.streams) {
      if (!s) continue;
      if (s === shown || time === undefined) {
        updateActor(s, s === shown ? stateAt(shown.position) : s.head);
        continue;
      }
      // The last record at or before that time (the times of a stream never go back).
      let low = 0;
      let high = s.records.length;
      while (low < high) {
        const middle = (low + high) >> 1;
        if (s.records[middle].time <= time) low = middle + 1;
        else high = middle;
      }
      updateActor(s, stateAt(low - 1, s));
    }
  }

  // The leaf states of s's configuration (its newest, or `state`), as its box shows them.
  function updateActor(s, state = s.head) {
    const box = actorBox(s.actor);
    if (!box) return;
    const d = s.reader.dictionary;
    const active = [...state.active];
    const parents = new Set(active.map((n) => d.states[n]?.parent));
    const leaves = active.filter((n) => !parents.has(n) && d.states[n] && d.states[n].kind !== StateKind.top).sort((a, b) => a - b);
    const text = leaves.map((n) => d.stateName(n)).join(' ');
    if (box.dataset.states === text) return;
    box.dataset.states = text;
    const line = box.querySelector('.states');
    const width = Number(box.querySelector('.shape').getAttribute('width')) - 20;
    let shown = text;
    while (shown.length > 1 && measure(shown, SMALL_FONT) > width) shown = `${shown.slice(0, -2)}…`;
    line.textContent = shown;
    box.querySelector('title').textContent = `${s.actor >= 0 ? app.system.actors[s.actor].name : ''}: ${text || '(no configuration yet)'}`;
  }

  // Live: an actor whose transitions fired pulses for a moment.
  const pulseTimers = new Map();
  function pulseActor(i) {
    const box = actorBox(i);
    if (!box) return;
    box.classList.remove('pulse');
    void box.getBoundingClientRect();
    box.classList.add('pulse');
    clearTimeout(pulseTimers.get(i));
    pulseTimers.set(i, setTimeout(() => box.classList.remove('pulse'), FLASH_MS));
  }

  function markSelected() {
    for (const box of document.querySelectorAll('#system-svg .actor')) box.classList.toggle('selected', Number(box.dataset.actor) === app.stream.actor);
  }

  /** Shows actor i's chart, members, log and timeline; commands go to it. */
  function selectActor(i) {
    const s = app.streams[i];
    if (!app.system || !s) return false;
    app.stream = s;
    s.log = { from: 0, to: -1 };
    $('log').replaceChildren();
    app.chart = null;
    app.chartSignature = '';
    $('chart').replaceChildren(placeholder('Waiting for the trace\u2019s dictionary…'));
    markSelected();
    scheduleLayout();
    renderEventButtons();
    renderMembersTable();
    show(s.following ? s.records.length - 1 : s.position);
    updateCounters();
    return true;
  }

  // ---- Counters, wiring, start ----------------------------------------------------------------

  function updateCounters() {
    const r = app.reader;
    const counters = $('counters');
    counters.textContent = `${r.frames} frames · ${r.missing} missing · ${r.skippedBytes} bytes skipped · ${r.malformed} malformed`;
    counters.classList.toggle('warn', r.missing + r.skippedBytes + r.malformed > 0);
  }

  function wire() {
    $('timeline').addEventListener('input', (e) => seek(Number(e.target.value)));
    $('step-back').addEventListener('click', () => seek(app.position - 1));
    $('step-forward').addEventListener('click', () => seek(app.position + 1));
    $('live').addEventListener('click', follow);
    $('log').addEventListener('click', (e) => {
      const line = e.target.closest('.line');
      if (line) seek(Number(line.dataset.index) - app.dropped);
    });
    $('show-cycles').addEventListener('change', (e) => $('log').classList.toggle('hide-cycles', !e.target.checked));
    $('zoom-in').addEventListener('click', () => zoom(1.25));
    $('zoom-out').addEventListener('click', () => zoom(1 / 1.25));
    $('zoom-fit').addEventListener('click', () => {
      app.zoom = app.zoom === 'fit' ? 1 : 'fit';
      applyZoom();
    });
    new ResizeObserver(() => app.zoom === 'fit' && applyZoom()).observe($('chart'));
    new ResizeObserver(fitSystem).observe($('system'));
    $('set-form').addEventListener('submit', (e) => {
      e.preventDefault();
      const member = $('set-member').value;
      const value = $('set-value').value.trim();
      if (!member || !value) {
        setStatus('set: choose a member and give a value', 'error');
        return;
      }
      command(`set ${actorWord()}${member} ${value}`);
    });
    for (const name of ['pause', 'resume', 'step']) $(name).addEventListener('click', () => command(name));
  }

  async function start() {
    wire();
    updateTimeline();
    updateCounters();
    const trace = new URLSearchParams(location.search).get('trace');
    if (trace) {
      startReplay();
      await loadUrl(trace);
      return;
    }
    if (location.protocol === 'http:' || location.protocol === 'https:') {
      try {
        app.info = await fetchInfo();
      } catch {
        app.info = null;
      }
    }
    if (!app.info) {
      startReplay();
      setStatus('Open a recorded trace (.bsctrace) to replay it.');
      return;
    }
    app.mode = 'live';
    $('mode').textContent = 'live';
    if (app.info.chart) $('chart-name').textContent = app.info.chart;
    if (app.info.system === true && Array.isArray(app.info.actors)) startSystem(app.info);
    renderControls();
    poll();
  }

  window.bscInspector = {
    get ready() {
      return app.ready;
    },
    get dictionary() {
      return app.reader.dictionary;
    },
    get mode() {
      return app.mode;
    },
    get following() {
      return app.following;
    },
    get records() {
      return app.records;
    },
    active: activeNames,
    position: () => app.position,
    get system() {
      return app.system !== null;
    },
    /** A system's actors: their names and the leaf states each box shows. */
    actors: () => (app.system ? app.system.actors.map((a, i) => ({ name: a.name, states: actorBox(i)?.dataset.states ?? null })) : []),
    /** The place of the actor whose panes are shown (-1 for a machine). */
    get selected() {
      return app.stream.actor;
    },
    select: (i) => selectActor(i),
  };

  start();
})();
