// The report page: fills the table, draws the charts with Chart.js and the cut with three.js
// from the JSON the program embedded (job/html_report.cpp).
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('tubemesh-data').textContent);
  const report = data.report;
  const kindNames = ['tet', 'pyramid', 'hex'];
  const kindColours = ['#5b9bd5', '#ed7d31', '#70ad47'];

  // JSON has no infinity (an inverted cell's aspect ratio): it arrives as null.
  function fixed(x) { return typeof x === 'number' ? x.toFixed(3) : 'inf'; }

  function text(tag, content, cls) {
    const e = document.createElement(tag);
    e.textContent = content;
    if (cls) e.className = cls;
    return e;
  }

  function fillSummary() {
    const s = report.sizes;
    document.title = 'tubemesh report: ' + report.source;
    document.getElementById('summary').textContent =
      report.source + ' (' + report.format + '), stage ' + report.stage + ': ' + report.tubes + ' tube(s), S = ' +
      s.S.toPrecision(6) + ', St = ' + s.St.toPrecision(6) + '; ' + report.nodes + ' nodes, ' + report.hexes +
      ' hexahedra, ' + report.pyramids + ' pyramids, ' + report.tets + ' tetrahedra in ' +
      report.total_seconds.toFixed(3) + ' s';
    const warnings = document.getElementById('warnings');
    report.warnings.forEach(function (w) { warnings.appendChild(text('li', w)); });
  }

  function fillTable() {
    const table = document.getElementById('table1');
    data.table.forEach(function (row) {
      const tr = document.createElement('tr');
      if (row[0]) tr.className = 'first';
      tr.appendChild(text('td', row[0]));
      tr.appendChild(text('td', row[1]));
      tr.appendChild(text('td', row[2], 'value'));
      table.appendChild(tr);
    });
    document.getElementById('table-legend').textContent = data.table_legend;
  }

  // Per pipe: how much of its wall is under a hex ring, how thick the ring is, and why.
  function fillPipes() {
    const pipes = report.pipes;
    if (!pipes || pipes.length === 0) return;
    document.getElementById('ring-share').textContent =
      'Hex rings cover ' + (100 * report.ring_share).toFixed(1) + ' % of the pipes\' wall area.';
    const table = document.getElementById('pipes');
    const head = document.createElement('tr');
    ['ring', 'wall faces', 'wall area', 'under a ring', 'thickness', 'why thinned or none'].forEach(function (h) {
      head.appendChild(text('th', h));
    });
    table.appendChild(head);
    pipes.forEach(function (p) {
      const tr = document.createElement('tr');
      tr.appendChild(text('td', p.ring || 'none'));
      tr.appendChild(text('td', p.faces.join(', ')));
      tr.appendChild(text('td', p.wall_area.toPrecision(4), 'value'));
      tr.appendChild(text('td', (100 * p.ring_share).toFixed(0) + ' %', 'value'));
      const t = p.ring_thickness;
      tr.appendChild(text('td', p.ring ? t.min.toPrecision(4) + ' to ' + t.max.toPrecision(4) : '-', 'value'));
      tr.appendChild(text('td', p.reason));
      table.appendChild(tr);
    });
    document.getElementById('pipes-section').hidden = false;
  }

  // The paper's column beside this mesh's, for one of the paper's three examples.
  function fillPaperTable() {
    const paper = report.paper_table1;
    if (!paper) return;
    const cell = function (v, key) {
      if (v === null) return '-';
      const whole = ['elements', 'tets', 'pyramids', 'hexes', 'nodes', 'all_tet_reference'].indexOf(key) >= 0;
      return whole ? String(v) : v.toFixed(6);
    };
    document.getElementById('paper-title').textContent =
      "The paper's Table 1, Example " + paper.example + ' (' + paper.preset + '), beside this mesh';
    const table = document.getElementById('paper-table');
    const head = document.createElement('tr');
    ['', 'paper', 'this mesh'].forEach(function (h) { head.appendChild(text('th', h)); });
    table.appendChild(head);
    paper.rows.forEach(function (row) {
      const tr = document.createElement('tr');
      tr.appendChild(text('td', row.label));
      tr.appendChild(text('td', cell(row.paper, row.key), 'value'));
      tr.appendChild(text('td', cell(row.this_mesh, row.key), 'value'));
      table.appendChild(tr);
    });
    document.getElementById('paper-section').hidden = false;
  }

  function drawPhases() {
    const phases = report.phases;
    new Chart(document.getElementById('phases'), {
      type: 'bar',
      data: {
        labels: phases.map(function (p) { return p.name; }),
        datasets: [{ label: 'wall time (s)', data: phases.map(function (p) { return p.seconds; }),
                     backgroundColor: '#5b9bd5' }]
      },
      options: { indexAxis: 'y', animation: false, responsive: false,
                 plugins: { legend: { display: false }, title: { display: true, text: 'Wall time per phase (s)' } } }
    });
  }

  function drawHistograms() {
    const box = document.getElementById('histograms');
    data.histograms.forEach(function (h) {
      const canvas = document.createElement('canvas');
      canvas.width = 360;
      canvas.height = 240;
      canvas.className = 'histogram';
      box.appendChild(canvas);
      const step = (h.hi - h.lo) / h.counts.length;
      const labels = h.counts.map(function (_, i) { return (h.lo + i * step).toFixed(2); });
      const colour = kindColours[kindNames.indexOf(h.kind)];
      new Chart(canvas, {
        type: 'bar',
        data: { labels: labels, datasets: [{ label: h.label, data: h.counts, backgroundColor: colour }] },
        options: {
          animation: false, responsive: false,
          scales: { x: { title: { display: true, text: h.higher_is_better ? '1 is best' : '1 is best, larger is worse' } },
                    y: { beginAtZero: true } },
          plugins: { legend: { display: false },
                     title: { display: true, text: h.label + ' (' + h.count + ' cells, min ' + fixed(h.min) +
                              ', mean ' + fixed(h.mean) + ', max ' + fixed(h.max) + ')' } }
        }
      });
    });
  }

  // Triangles of the cut's visible faces, one geometry per kind so each can be hidden.
  function drawView() {
    const view = data.view;
    const canvas = document.getElementById('view');
    const renderer = new THREE.WebGLRenderer({ canvas: canvas, antialias: true, preserveDrawingBuffer: true });
    renderer.setClearColor(0xffffff);
    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera(40, canvas.width / canvas.height, 0.01, 100);
    camera.position.set(1.3, 1.0, 2.2);
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const light = new THREE.DirectionalLight(0xffffff, 0.6);
    light.position.set(1, 2, 3);
    scene.add(light);

    const p = view.points, cells = view.cells;
    const byKind = [[], [], []];
    for (let i = 0; i < view.faces.length;) {
      const cell = view.faces[i], size = view.faces[i + 1];
      byKind[cells.kind[cell]].push({ cell: cell, nodes: view.faces.slice(i + 2, i + 2 + size) });
      i += 2 + size;
    }
    const kindColour = kindColours.map(function (c) { return new THREE.Color(c); });
    const groups = [];
    const qualityColour = new THREE.Color();
    byKind.forEach(function (faces, kind) {
      const positions = [], kindColours = [], qualityColours = [], edges = [];
      faces.forEach(function (f) {
        const q = Math.max(0, Math.min(1, cells.quality[f.cell]));
        qualityColour.setHSL(0.66 * q, 0.9, 0.5);
        const tris = f.nodes.length === 4 ? [[0, 1, 2], [0, 2, 3]] : [[0, 1, 2]];
        tris.forEach(function (t) {
          t.forEach(function (k) {
            const n = f.nodes[k];
            positions.push(p[3 * n], p[3 * n + 1], p[3 * n + 2]);
            kindColours.push(kindColour[kind].r, kindColour[kind].g, kindColour[kind].b);
            qualityColours.push(qualityColour.r, qualityColour.g, qualityColour.b);
          });
        });
        for (let k = 0; k < f.nodes.length; ++k) {
          const a = f.nodes[k], b = f.nodes[(k + 1) % f.nodes.length];
          edges.push(p[3 * a], p[3 * a + 1], p[3 * a + 2], p[3 * b], p[3 * b + 1], p[3 * b + 2]);
        }
      });
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
      const colours = { kind: new THREE.Float32BufferAttribute(kindColours, 3),
                        quality: new THREE.Float32BufferAttribute(qualityColours, 3) };
      geometry.setAttribute('color', colours.kind);
      geometry.computeVertexNormals();
      const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({
        vertexColors: THREE.VertexColors, side: THREE.DoubleSide,
        polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
      const lineGeometry = new THREE.BufferGeometry();
      lineGeometry.setAttribute('position', new THREE.Float32BufferAttribute(edges, 3));
      const lines = new THREE.LineSegments(lineGeometry, new THREE.LineBasicMaterial({ color: 0x333333 }));
      const group = new THREE.Group();
      group.add(mesh);
      group.add(lines);
      scene.add(group);
      groups.push({ group: group, geometry: geometry, colours: colours });
    });

    // Worst cells: a marker at the centroid of their visible nodes, drawn over everything.
    const marker = new THREE.SphereBufferGeometry(0.025, 12, 8);
    const markerMaterial = new THREE.MeshBasicMaterial({ color: 0xff0000, depthTest: false });
    const worstTable = document.getElementById('worst');
    worstTable.appendChild((function () {
      const tr = document.createElement('tr');
      ['worst in the cut', 'cell', 'primary measure'].forEach(function (h) { tr.appendChild(text('th', h)); });
      return tr;
    })());
    view.worst.forEach(function (cell) {
      const c = new THREE.Vector3(), n = { count: 0 };
      byKind[cells.kind[cell]].forEach(function (f) {
        if (f.cell !== cell) return;
        f.nodes.forEach(function (k) { c.x += p[3 * k]; c.y += p[3 * k + 1]; c.z += p[3 * k + 2]; n.count++; });
      });
      if (n.count > 0) {
        const m = new THREE.Mesh(marker, markerMaterial);
        m.position.copy(c.multiplyScalar(1 / n.count));
        m.renderOrder = 1;
        groups[cells.kind[cell]].group.add(m);
      }
      const tr = document.createElement('tr');
      tr.appendChild(text('td', kindNames[cells.kind[cell]]));
      tr.appendChild(text('td', String(cells.index[cell])));
      tr.appendChild(text('td', cells.quality[cell].toFixed(4), 'value'));
      worstTable.appendChild(tr);
    });

    const controls = new THREE.OrbitControls(camera, canvas);
    function render() { renderer.render(scene, camera); }
    controls.addEventListener('change', render);
    document.getElementById('colour-mode').addEventListener('change', function (e) {
      groups.forEach(function (g) { g.geometry.setAttribute('color', g.colours[e.target.value]); });
      render();
    });
    ['show-tets', 'show-pyramids', 'show-hexes'].forEach(function (id, kind) {
      document.getElementById(id).addEventListener('change', function (e) {
        groups[kind].group.visible = e.target.checked;
        render();
      });
    });
    render();
  }

  fillSummary();
  fillPipes();
  fillTable();
  fillPaperTable();
  drawPhases();
  drawHistograms();
  drawView();
})();
