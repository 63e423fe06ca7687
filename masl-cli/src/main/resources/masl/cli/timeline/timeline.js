// Draws the timeline of a MASL trace (the JSON of #timeline-data, written by TimelineHtml) as SVG,
// with zoom and pan over time (wheel, drag, minimap) and filters by agent, block and kind of record.
// Everything is redrawn for the visible interval only, merging shapes that fall within one pixel,
// so that a trace of thousands of records stays light.
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('timeline-data').textContent);
  var NS = 'http://www.w3.org/2000/svg';
  var LANE = 28, WAVE = 14, AXIS = 22, MINI_LANE = 6, PAD = 12;
  var KINDS = [
    ['membership', 'blocks', 'the spans of each agent in its innermost block'],
    ['waves', 'waves', 'the waves of each block, above the lanes'],
    ['trips', 'barrier trips', 'a synchronisation barrier letting its agents go on'],
    ['invocations', 'invocations', 'an arrow from the caller to the callee; red and crossed when denied'],
    ['events', 'events', 'an emission (filled triangle) linked to the reactions (upward triangles)'],
    ['failures', 'failures', 'an agent whose program died'],
    ['markers', 'other records', 'an agent entering a block for the first time or leaving its outermost block, a countermeasure fired']
  ];
  var STATES = ['running', 'held at the entry barrier', 'held at the exit barrier'];
  var byRecord = data.clock === 'record';
  var length = Math.max(1, data.length);
  var minSpan = byRecord ? Math.min(length, 4) : Math.min(length, 1000);
  var view = [0, length];
  var hidden = { agents: {}, blocks: {}, kinds: {} };
  var nameOf = {};
  data.agents.forEach(function (a) { nameOf[a.id] = a.name; });
  var chart = document.getElementById('chart');
  var minimap = document.getElementById('minimap');
  var layout = null;
  var pending = false;

  function el(tag, attrs, parent, title) {
    var node = document.createElementNS(NS, tag);
    for (var name in attrs) {
      if (attrs[name] !== undefined && attrs[name] !== null) node.setAttribute(name, attrs[name]);
    }
    if (title) {
      var tip = document.createElementNS(NS, 'title');
      tip.textContent = title;
      node.appendChild(tip);
    }
    if (parent) parent.appendChild(node);
    return node;
  }

  function text(parent, x, y, content, cls, title) {
    var node = el('text', { x: x, y: y, 'class': cls }, parent, title);
    node.appendChild(document.createTextNode(content));
    return node;
  }

  function agentName(id) {
    return id < 0 ? 'outside the mission' : (nameOf[id] !== undefined ? nameOf[id] : 'agent ' + id);
  }

  // ---- time and its labels: the unit fits the times shown, the decimals the step between ticks.
  function niceStep(raw) {
    var power = Math.pow(10, Math.floor(Math.log10(raw)));
    var m = raw / power;
    return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * power;
  }

  function unitFor(largest) {
    if (largest >= 1e9) return [1e9, 's'];
    if (largest >= 1e6) return [1e6, 'ms'];
    if (largest >= 1e3) return [1e3, '\u00b5s'];
    return [1, 'ns'];
  }

  function formatter(step, largest) {
    if (byRecord) return function (t) { return '#' + Math.round(t); };
    var unit = unitFor(largest);
    var decimals = Math.max(0, Math.min(9, -Math.floor(Math.log10(step / unit[0]) + 1e-9)));
    return function (t) { return (t / unit[0]).toFixed(decimals) + ' ' + unit[1]; };
  }

  var exact = formatter(byRecord ? 1 : Math.max(1, length / 1000), length);

  // ---- filters and the controls that set them.
  function visibleAgents() {
    return data.agents.filter(function (a) { return !hidden.agents[a.id]; });
  }

  function shown(kind) {
    return !hidden.kinds[kind];
  }

  function controls() {
    var box = document.getElementById('controls');
    var nav = document.createElement('div');
    [['\u2212', 'zoom out', function () { zoomAt(2, (view[0] + view[1]) / 2); }],
     ['+', 'zoom in', function () { zoomAt(0.5, (view[0] + view[1]) / 2); }],
     ['whole run', 'show the whole run', function () { setView(0, length); }]].forEach(function (b) {
      var button = document.createElement('button');
      button.textContent = b[0];
      button.title = b[1];
      button.className = b[1].replace(/ /g, '-');
      button.addEventListener('click', b[2]);
      nav.appendChild(button);
    });
    var interval = document.createElement('span');
    interval.id = 'interval';
    nav.appendChild(interval);
    box.appendChild(nav);
    box.appendChild(filter('agent', 'Agents', data.agents.map(function (a) { return [a.id, a.name, null]; }), hidden.agents));
    box.appendChild(filter('block', 'Blocks', data.blocks.map(function (b, i) { return [i, b.name, b.color]; }), hidden.blocks));
    box.appendChild(filter('kind', 'Records', KINDS.map(function (k) { return [k[0], k[1], null, k[2]]; }), hidden.kinds));
  }

  function filter(kind, title, items, set) {
    var group = document.createElement('fieldset');
    group.className = 'filter-' + kind;
    var legend = document.createElement('legend');
    legend.textContent = title;
    group.appendChild(legend);
    items.forEach(function (item) {
      var label = document.createElement('label');
      if (item[3]) label.title = item[3];
      var box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = true;
      box.value = String(item[0]);
      box.setAttribute('data-filter', kind);
      box.addEventListener('change', function () {
        if (box.checked) delete set[item[0]]; else set[item[0]] = true;
        drawMinimap();
        redraw();
      });
      label.appendChild(box);
      if (item[2]) {
        var swatch = document.createElement('i');
        swatch.style.background = item[2];
        label.appendChild(swatch);
      }
      label.appendChild(document.createTextNode(item[1]));
      group.appendChild(label);
    });
    return group;
  }

  // ---- the view: which interval is drawn.
  function setView(start, end) {
    var span = Math.min(length, Math.max(minSpan, end - start));
    start = Math.max(0, Math.min(length - span, start));
    view = [start, start + span];
    redraw();
  }

  function zoomAt(factor, at) {
    var span = view[1] - view[0];
    var next = Math.min(length, Math.max(minSpan, span * factor));
    setView(at - (at - view[0]) * next / span, at - (at - view[0]) * next / span + next);
  }

  function redraw() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(function () { pending = false; draw(); });
  }

  // ---- the chart.
  function labelWidth() {
    var probe = el('svg', {}, document.body);
    var widest = 40;
    data.agents.forEach(function (a) {
      widest = Math.max(widest, text(probe, 0, 0, a.name, 'agent').getComputedTextLength());
    });
    data.blocks.forEach(function (b) {
      widest = Math.max(widest, text(probe, 0, 0, 'waves ' + b.name, 'wavelabel').getComputedTextLength());
    });
    document.body.removeChild(probe);
    return Math.ceil(Math.min(260, widest)) + 14;
  }

  var left = labelWidth();

  function draw() {
    var width = Math.max(640, document.documentElement.clientWidth - 2 * PAD - 4);
    var agents = visibleAgents();
    var waveRows = shown('waves') ? data.blocks.map(function (b, i) { return i; }).filter(function (i) { return !hidden.blocks[i]; }) : [];
    var lanesTop = AXIS + 4 + waveRows.length * WAVE + (waveRows.length ? 6 : 0);
    var height = lanesTop + agents.length * LANE + 8;
    var plot = { left: left, right: width - 4 };
    var scale = (plot.right - plot.left) / (view[1] - view[0]);
    var laneOf = {};
    agents.forEach(function (a, row) { laneOf[a.id] = lanesTop + row * LANE; });
    layout = { plot: plot, scale: scale, lanesTop: lanesTop };
    function x(t) { return plot.left + (t - view[0]) * scale; }
    function inView(s, e) { return e >= view[0] && s <= view[1]; }

    while (chart.firstChild) chart.removeChild(chart.firstChild);
    chart.setAttribute('width', width);
    chart.setAttribute('height', height);
    chart.setAttribute('data-view-start', view[0]);
    chart.setAttribute('data-view-end', view[1]);
    chart.setAttribute('data-plot-left', plot.left);
    chart.setAttribute('data-plot-right', plot.right);
    var defs = el('defs', {}, chart);
    el('rect', { x: plot.left, y: 0, width: plot.right - plot.left, height: height }, el('clipPath', { id: 'plot' }, defs));
    var arrow = el('marker', { id: 'arrow', viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse' }, defs);
    el('path', { d: 'M0,0 L10,5 L0,10 z', fill: '#1a1a1a' }, arrow);
    var redArrow = el('marker', { id: 'arrow-denied', viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse' }, defs);
    el('path', { d: 'M0,0 L10,5 L0,10 z', fill: '#c00' }, redArrow);
    var hatch = el('pattern', { id: 'hatch', width: 6, height: 6, patternUnits: 'userSpaceOnUse', patternTransform: 'rotate(45)' }, defs);
    el('line', { x1: 0, y1: 0, x2: 0, y2: 6, stroke: 'white', 'stroke-width': 3 }, hatch);

    axis(x, plot, height);
    var clipped = el('g', { 'clip-path': 'url(#plot)' }, chart);
    waves(clipped, waveRows, x, inView);
    var labels = el('g', {}, chart);
    waveRows.forEach(function (b, row) {
      text(labels, plot.left - 6, AXIS + 4 + row * WAVE + WAVE - 2, 'waves ' + data.blocks[b].name, 'wavelabel');
    });
    agents.forEach(function (a) {
      text(labels, plot.left - 6, laneOf[a.id] + LANE / 2 + 4, a.name, 'agent', 'agent ' + a.id + ': ' + a.name);
      el('rect', { 'class': 'lane', x: plot.left, y: laneOf[a.id] + 3, width: plot.right - plot.left, height: LANE - 6 }, clipped);
      if (shown('membership')) spans(clipped, a, laneOf[a.id], x, inView);
    });
    if (shown('trips')) trips(clipped, x, lanesTop, height);
    var marks = el('g', { 'class': 'marks' }, clipped);
    var placed = [];
    if (shown('events')) events(marks, laneOf, x, placed);
    if (shown('invocations')) invocations(marks, laneOf, x, lanesTop, placed);
    if (shown('failures')) failures(marks, laneOf, x, placed);
    if (shown('markers')) markers(marks, laneOf, x, placed);
    labelMarks(el('g', { 'class': 'labels' }, clipped), placed, plot);
    document.getElementById('interval').textContent = 'showing ' + exact(view[0]) + ' \u2013 ' + exact(view[1])
        + ' of ' + exact(length) + (byRecord ? ' (virtual clock: time is the record number)' : '');
    brush();
  }

  function axis(x, plot, height) {
    var span = view[1] - view[0];
    var step = niceStep(Math.max(byRecord ? 1 : 1e-9, span / Math.max(2, (plot.right - plot.left) / 110)));
    var format = formatter(step, view[1]);
    var g = el('g', { 'class': 'axis' }, chart);
    for (var t = Math.ceil(view[0] / step) * step; t <= view[1] + step * 1e-6; t += step) {
      var at = x(t);
      el('line', { 'class': 'tick', x1: at, y1: AXIS - 4, x2: at, y2: height }, g);
      var label = text(g, at, AXIS - 8, format(t), 'axis');
      var w = label.getComputedTextLength();
      // Labels stay whole: one at an edge is drawn inside the plot rather than across it.
      label.setAttribute('text-anchor', at - w / 2 < plot.left ? 'start' : at + w / 2 > plot.right ? 'end' : 'middle');
      if (at - w / 2 < plot.left) label.setAttribute('x', Math.max(at, plot.left));
    }
  }

  // Shapes in one row that fall within a pixel of the previous one of the same kind are one shape.
  function merger(parent) {
    var last = null;
    return function (x0, x1, key, attrs, title) {
      x1 = Math.max(x1, x0 + (x1 - x0 < 0.5 ? 2 : 1));
      if (last && last.key === key && x0 <= last.x1 + 0.5) {
        last.x1 = Math.max(last.x1, x1);
        last.node.setAttribute('width', last.x1 - last.x0);
        return;
      }
      attrs.x = x0;
      attrs.width = x1 - x0;
      last = { key: key, x0: x0, x1: x1, node: el('rect', attrs, parent, title) };
    };
  }

  function waves(parent, rows, x, inView) {
    var merge = rows.map(function () { return merger(parent); });
    data.waves.forEach(function (w) {
      var row = rows.indexOf(w[0]);
      if (row < 0 || !inView(w[2], w[3])) return;
      var b = data.blocks[w[0]];
      merge[row](x(w[2]), x(w[3]), w[0], { 'class': 'wave', 'data-block': b.name, y: AXIS + 4 + row * WAVE, height: WAVE - 2, fill: b.color },
          'block ' + b.name + ', wave ' + w[1] + ': ' + exact(w[2]) + ' \u2013 ' + exact(w[3]));
    });
  }

  // A span of no time (a block entered and left within one step of a simulated clock) is drawn
  // narrow, after the others, so that the block around it does not cover it.
  function spans(parent, agent, top, x, inView) {
    var merge = merger(parent);
    var instants = [];
    agent.spans.forEach(function (s) {
      if (hidden.blocks[s[2]] || !inView(s[0], s[1])) return;
      var b = data.blocks[s[2]];
      var title = agent.name + ' in ' + b.name + ' (' + STATES[s[3]] + '): ' + exact(s[0]) + ' \u2013 ' + exact(s[1]);
      var attrs = { 'class': 'span' + (s[3] ? ' held' : ''), 'data-block': b.name, y: top + 3, height: LANE - 6, fill: b.color };
      if (s[0] === s[1]) {
        instants.push([x(s[0]), s[2], attrs, title]);
        return;
      }
      merge(x(s[0]), x(s[1]), s[2] + '/' + s[3], attrs, title);
      if (s[3]) {
        el('rect', { x: x(s[0]), y: top + 3, width: Math.max(1, x(s[1]) - x(s[0])), height: LANE - 6, fill: 'url(#hatch)' }, parent);
      }
    });
    var mergeInstants = merger(parent);
    instants.forEach(function (i) { mergeInstants(i[0] - 1, i[0] - 1, i[1], i[2], i[3]); });
  }

  function trips(parent, x, top, height) {
    var visible = data.trips.filter(function (t) { return t[0] >= view[0] && t[0] <= view[1]; });
    var opacity = visible.length > 200 ? 0.15 : 1;
    var lastX = -1;
    visible.forEach(function (t) {
      var at = Math.round(x(t[0])) + 0.5;
      if (at - lastX < 1) return;
      lastX = at;
      el('line', { 'class': 'trip', x1: at, y1: top, x2: at, y2: height - 4, 'stroke-opacity': opacity, 'shape-rendering': 'crispEdges' }, parent,
          'barrier trip at ' + exact(t[0]) + ': domain ' + t[1] + ', ' + t[2] + ' agents went on');
    });
  }

  function where(source) {
    return source ? '\n' + source : '';
  }

  function triangle(parent, at, y, up, cls, title) {
    var d = up ? 'M' + at + ',' + (y - 9) + ' l5,9 l-10,0 z' : 'M' + at + ',' + (y + 9) + ' l5,-9 l-10,0 z';
    return el('path', { 'class': cls, d: d }, parent, title);
  }

  function events(parent, laneOf, x, placed) {
    data.events.forEach(function (e) {
      if (laneOf[e.agent] === undefined || e.t < view[0] || e.t > view[1]) return;
      var at = x(e.t), top = laneOf[e.agent];
      if (e.kind === 'reacted') {
        var emission = data.events[e.emission];
        if (emission && laneOf[emission.agent] !== undefined && (emission.agent !== e.agent || emission.t !== e.t)) {
          el('line', { 'class': 'event-link', x1: x(emission.t), y1: laneOf[emission.agent] + 12, x2: at, y2: top + LANE - 12 }, parent);
        }
        triangle(parent, at, top + LANE - 3, true, 'reacted', agentName(e.agent) + ' reacts to ' + e.name + ' (reaction of block '
            + e.detail + ') at ' + exact(e.t) + where(e.source));
        placed.push({ x: at, y: top + LANE - 4, text: 'react ' + e.name, kind: 'events' });
      } else {
        triangle(parent, at, top + 3, false, e.kind, agentName(e.agent) + (e.kind === 'emitted' ? ' emits ' : ' drops ') + e.name
            + (e.detail ? ' "' + e.detail + '"' : '') + ' at ' + exact(e.t) + where(e.source));
        placed.push({ x: at, y: top + 11, text: (e.kind === 'emitted' ? 'emit ' : 'drop ') + e.name, kind: 'events' });
      }
    });
  }

  function invocations(parent, laneOf, x, lanesTop, placed) {
    data.invocations.forEach(function (c) {
      if (c.resolved < view[0] || c.made > view[1] || laneOf[c.to] === undefined) return;
      var fromY = c.from < 0 ? lanesTop - 2 : laneOf[c.from];
      if (fromY === undefined) return;
      var toY = laneOf[c.to];
      var x1 = x(c.made), x2 = x(c.resolved);
      var title = agentName(c.from) + ' \u2192 ' + agentName(c.to) + '.' + c.member + ': ' + c.outcome
          + (c.state ? ' by permeability state "' + c.state + '"' : '') + ', ' + exact(c.made)
          + (c.resolved !== c.made ? ' \u2013 ' + exact(c.resolved) : '') + where(c.source);
      var cls = 'invocation ' + c.outcome;
      var marker = c.outcome === 'denied' ? 'url(#arrow-denied)' : 'url(#arrow)';
      var endY;
      if (c.from === c.to) {
        endY = toY + LANE - 4;
        el('path', { 'class': cls, d: 'M' + x1 + ',' + (toY + 4) + ' C' + (x1 + 26) + ',' + (toY + 2) + ' ' + (x2 + 26) + ',' + endY
            + ' ' + x2 + ',' + endY, 'marker-end': marker }, parent, title);
      } else {
        var down = toY > fromY;
        var startY = fromY + (down ? LANE - 4 : 4);
        endY = toY + (down ? 4 : LANE - 4);
        el('line', { 'class': cls, x1: x1, y1: startY, x2: x2, y2: endY, 'marker-end': marker }, parent, title);
      }
      if (c.outcome === 'denied') {
        text(parent, x2 + 3, endY + (endY > toY + LANE / 2 ? -2 : 10), '\u2715', 'denied', title);
      }
      placed.push({ x: (x1 + x2) / 2 + 4, y: (c.from === c.to ? toY + LANE / 2 : (fromY + toY) / 2 + LANE / 2) + 4,
        text: (c.from === c.to ? '' : '\u2192 ' + agentName(c.to) + '.') + c.member + (c.outcome === 'denied' ? ' denied (' + c.state + ')' : ''), kind: 'invocations', important: true });
    });
  }

  function failures(parent, laneOf, x, placed) {
    data.failures.forEach(function (f) {
      if (laneOf[f.agent] === undefined || f.t < view[0] || f.t > view[1]) return;
      var at = x(f.t);
      var mark = text(parent, at, laneOf[f.agent] + LANE / 2 + 5, '\u2716', 'failure', agentName(f.agent) + ' failed at ' + exact(f.t)
          + ': ' + f.cause + where(f.source));
      mark.setAttribute('text-anchor', 'middle');
      placed.push({ x: at + 8, y: laneOf[f.agent] + LANE / 2 + 4, text: 'failed', kind: 'failures', important: true });
    });
  }

  function markers(parent, laneOf, x, placed) {
    data.markers.forEach(function (m) {
      if (laneOf[m.agent] === undefined || m.t < view[0] || m.t > view[1]) return;
      var at = x(m.t), top = laneOf[m.agent];
      var title = agentName(m.agent) + ': ' + m.label + ' at ' + exact(m.t) + where(m.source);
      if (m.kind === 'left') {
        el('rect', { 'class': 'left-mark', x: at - 1, y: top + 1, width: 2.5, height: LANE - 2 }, parent, title);
        placed.push({ x: at + 4, y: top + LANE / 2 + 4, text: m.label.replace(/ \(.*\)$/, ''), kind: 'markers', important: m.t < length });
      } else if (m.kind === 'first-entry') {
        el('path', { 'class': 'entry-mark', d: 'M' + at + ',' + (top + LANE - 2) + ' l4,5 l-8,0 z' }, parent, title);
        placed.push({ x: at + 2, y: top + LANE - 6, text: m.label, kind: 'markers', important: m.t > 0 });
      } else {
        el('path', { 'class': 'countermeasure', d: 'M' + at + ',' + (top + 6) + ' l5,8 l-5,8 l-5,-8 z' }, parent, title);
        placed.push({ x: at + 6, y: top + LANE / 2 + 4, text: m.label, kind: 'markers' });
      }
    });
  }

  // Marks are named on the lanes when there are few enough to read; the rare ones (invocations,
  // failures, an agent leaving before the end) always are. A label at the right edge goes left.
  function labelMarks(parent, placed, plot) {
    var few = placed.length <= 80;
    var taken = [];
    placed.forEach(function (p) {
      if (!few && !p.important) return;
      var label = text(parent, p.x + 4, p.y, p.text, 'label ' + p.kind);
      var w = label.getComputedTextLength();
      var x0 = p.x + 4;
      if (x0 + w > plot.right - 2) {
        x0 = p.x - 8 - w;
        label.setAttribute('x', x0);
      }
      var clash = taken.some(function (r) { return Math.abs(r.y - p.y) < 10 && x0 < r.x1 && x0 + w > r.x0; });
      if (clash && !p.important) {
        parent.removeChild(label);
        return;
      }
      taken.push({ x0: x0, x1: x0 + w, y: p.y });
    });
  }

  // ---- the minimap: the whole run, the visible interval as a brush.
  var miniScale = 1;

  function drawMinimap() {
    var width = Math.max(640, document.documentElement.clientWidth - 2 * PAD - 4);
    var agents = visibleAgents();
    var height = 6 + Math.max(1, agents.length) * MINI_LANE;
    while (minimap.firstChild) minimap.removeChild(minimap.firstChild);
    minimap.setAttribute('width', width);
    minimap.setAttribute('height', height);
    miniScale = (width - left - 4) / length;
    function x(t) { return left + t * miniScale; }
    text(minimap, left - 6, height / 2 + 4, 'whole run', 'wavelabel');
    agents.forEach(function (a, row) {
      var merge = merger(minimap);
      a.spans.forEach(function (s) {
        if (hidden.blocks[s[2]]) return;
        merge(x(s[0]), x(s[1]), s[2], { y: 3 + row * MINI_LANE, height: MINI_LANE - 1, fill: data.blocks[s[2]].color });
      });
    });
    data.invocations.concat(data.failures.map(function (f) { return { made: f.t }; })).forEach(function (c) {
      el('rect', { x: x(c.made) - 0.5, y: 0, width: 1.5, height: height, fill: '#c00' }, minimap);
    });
    el('rect', { 'class': 'brush', id: 'brush', y: 1, height: height - 2 }, minimap);
    brush();
  }

  function brush() {
    var b = document.getElementById('brush');
    if (!b) return;
    var x0 = left + view[0] * miniScale;
    b.setAttribute('x', x0);
    b.setAttribute('width', Math.max(3, (view[1] - view[0]) * miniScale));
  }

  // ---- interaction.
  function timeAt(clientX) {
    var box = chart.getBoundingClientRect();
    return view[0] + (clientX - box.left - layout.plot.left) / layout.scale;
  }

  chart.addEventListener('wheel', function (e) {
    e.preventDefault();
    var delta = e.deltaMode === 1 ? e.deltaY * 16 : e.deltaY;
    zoomAt(Math.exp(Math.max(-3, Math.min(3, delta * 0.002))), Math.max(view[0], Math.min(view[1], timeAt(e.clientX))));
  }, { passive: false });

  var drag = null;
  chart.addEventListener('mousedown', function (e) {
    if (e.button !== 0) return;
    drag = { x: e.clientX, view: view.slice(), scale: layout.scale };
    chart.classList.add('dragging');
    e.preventDefault();
  });
  minimap.addEventListener('mousedown', function (e) {
    if (e.button !== 0) return;
    var span = view[1] - view[0];
    var t = (e.clientX - minimap.getBoundingClientRect().left - left) / miniScale;
    if (t < view[0] || t > view[1]) setView(t - span / 2, t + span / 2);
    drag = { x: e.clientX, view: view.slice(), scale: -miniScale };
    e.preventDefault();
  });
  window.addEventListener('mousemove', function (e) {
    if (!drag) return;
    // Dragging the chart moves time with the pointer; dragging the brush moves the view itself.
    var dt = (e.clientX - drag.x) / drag.scale;
    setView(drag.view[0] - dt, drag.view[1] - dt);
  });
  window.addEventListener('mouseup', function () {
    drag = null;
    chart.classList.remove('dragging');
  });
  window.addEventListener('resize', function () { drawMinimap(); redraw(); });

  var counts = {
    denied: data.invocations.filter(function (c) { return c.outcome === 'denied'; }).length,
    emitted: data.events.filter(function (e) { return e.kind === 'emitted'; }).length,
    reacted: data.events.filter(function (e) { return e.kind === 'reacted'; }).length
  };
  document.getElementById('summary').textContent = [
    data.agents.length + ' agents', data.blocks.length + ' blocks', data.waves.length + ' waves',
    data.trips.length + ' barrier trips',
    data.invocations.length + ' invocations' + (counts.denied ? ' (' + counts.denied + ' denied)' : ''),
    counts.emitted + ' events emitted, ' + counts.reacted + ' reactions',
    data.failures.length + ' failures',
    'run of ' + exact(length) + (data.status ? ', ' + data.status.replace('_', ' ') : '')
  ].join(' \u00b7 ');
  // What each mark of the chart means, each drawn as the chart draws it (same classes, same shapes).
  function legend() {
    var box = document.getElementById('legend');
    var block = data.blocks.length ? data.blocks[0].color : '#888';
    var W = 26, H = 16;
    var items = [
      ['span', 'an agent in its innermost block (the block\u2019s colour)', function (g) {
        el('rect', { 'class': 'span', x: 1, y: 2, width: W - 2, height: H - 4, fill: block }, g);
      }],
      ['held', 'held at the block\u2019s entry or exit barrier', function (g) {
        var hatch = el('pattern', { id: 'legend-hatch', width: 6, height: 6, patternUnits: 'userSpaceOnUse', patternTransform: 'rotate(45)' },
            el('defs', {}, g));
        el('line', { x1: 0, y1: 0, x2: 0, y2: 6, stroke: 'white', 'stroke-width': 3 }, hatch);
        el('rect', { 'class': 'span held', x: 1, y: 2, width: W - 2, height: H - 4, fill: block }, g);
        el('rect', { x: 1, y: 2, width: W - 2, height: H - 4, fill: 'url(#legend-hatch)' }, g);
      }],
      ['wave', 'a wave of the block (above the lanes)', function (g) {
        el('rect', { 'class': 'wave', x: 1, y: 4, width: W - 2, height: H - 8, fill: block }, g);
      }],
      ['trip', 'a barrier trip', function (g) {
        el('line', { 'class': 'trip', x1: W / 2 + 0.5, y1: 0, x2: W / 2 + 0.5, y2: H, 'shape-rendering': 'crispEdges' }, g);
      }],
      ['invocation', 'an invocation, from the caller to the callee (dashed while pending)', function (g) {
        el('line', { 'class': 'invocation', x1: 2, y1: 3, x2: W - 6, y2: H - 4 }, g);
        el('path', { d: 'M' + (W - 2) + ',' + (H - 2) + ' l-7,-1 l4,-5 z', fill: '#1a1a1a' }, g);
      }],
      ['denied', 'an invocation denied by the callee\u2019s permeability state', function (g) {
        el('line', { 'class': 'invocation denied', x1: 2, y1: 3, x2: W - 10, y2: H - 4 }, g);
        text(g, W - 9, H - 2, '\u2715', 'denied');
      }],
      ['emitted', 'an event emitted', function (g) {
        triangle(g, W / 2, 3, false, 'emitted');
      }],
      ['reacted', 'a reaction to an event', function (g) {
        triangle(g, W / 2, H - 3, true, 'reacted');
      }],
      ['failure', 'an agent\u2019s program died', function (g) {
        text(g, W / 2 - 6, H - 2, '\u2716', 'failure');
      }],
      ['entry-mark', 'an agent entering a nested block for the first time', function (g) {
        el('path', { 'class': 'entry-mark', d: 'M' + W / 2 + ',' + (H - 8) + ' l4,5 l-8,0 z' }, g);
      }],
      ['left-mark', 'an agent leaving its outermost block', function (g) {
        el('rect', { 'class': 'left-mark', x: W / 2 - 1, y: 1, width: 2.5, height: H - 2 }, g);
      }],
      ['countermeasure', 'a countermeasure fired', function (g) {
        el('path', { 'class': 'countermeasure', d: 'M' + W / 2 + ',0 l5,8 l-5,8 l-5,-8 z' }, g);
      }]
    ];
    items.forEach(function (item) {
      var entry = document.createElement('span');
      entry.className = 'legend-' + item[0];
      var mark = el('svg', { width: W, height: H, 'aria-hidden': 'true' }, entry);
      item[2](mark);
      entry.appendChild(document.createTextNode(item[1]));
      box.appendChild(entry);
    });
  }

  controls();
  legend();
  drawMinimap();
  draw();
})();
