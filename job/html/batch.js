// The batch page: a summary line, bar charts per block (elements by kind, tet quality, time)
// with Chart.js, and the catalogue's table with a link to each block's own report.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('tubemesh-data').textContent);
  const blocks = data.blocks;
  const done = blocks.filter(function (b) { return b.status === 'done'; });
  const kindColours = { tet: '#5b9bd5', pyramid: '#ed7d31', hex: '#70ad47' };

  function fixed(x) { return typeof x === 'number' ? x.toFixed(4) : ''; }

  function summary() {
    const count = function (s) { return blocks.filter(function (b) { return b.status === s; }).length; };
    let elements = 0, seconds = 0;
    done.forEach(function (b) { elements += b.elements; seconds += b.seconds; });
    document.getElementById('summary').textContent =
      blocks.length + ' blocks: ' + count('done') + ' done, ' + count('failed') + ' failed, ' + count('pending') +
      ' pending; ' + elements + ' elements in ' + seconds.toFixed(1) + ' s of block time (' +
      (seconds > 0 ? Math.round(elements / seconds) : 0) + ' elements/s)';
    document.title = 'tubemesh batch: ' + blocks.length + ' blocks';
  }

  function bars(id, title, datasets, stacked) {
    new Chart(document.getElementById(id), {
      type: 'bar',
      data: { labels: done.map(function (b) { return b.id; }), datasets: datasets },
      options: { animation: false, responsive: false,
                 scales: { x: { stacked: stacked }, y: { stacked: stacked, beginAtZero: true } },
                 plugins: { title: { display: true, text: title } } }
    });
  }

  function table() {
    const t = document.getElementById('blocks');
    const head = ['block', 'status', 'elements', 'hexes', 'pyramids', 'tets', 's', 'elements/s', 'tet min',
                  'tet mean', 'pyramid min', 'hex J_m min', 'hex cond max', 'report'];
    const tr = document.createElement('tr');
    head.forEach(function (h) { const th = document.createElement('th'); th.textContent = h; tr.appendChild(th); });
    t.appendChild(tr);
    blocks.forEach(function (b) {
      const row = document.createElement('tr');
      row.className = 'block ' + b.status;
      const cells = [b.id, b.status === 'failed' ? 'failed: ' + b.error : b.status, b.elements, b.hexes, b.pyramids,
                     b.tets, b.seconds.toFixed(2), b.seconds > 0 ? Math.round(b.elements / b.seconds) : '',
                     b.tets ? fixed(b.tet_min) : '', b.tets ? fixed(b.tet_mean) : '',
                     b.pyramids ? fixed(b.pyramid_min) : '', b.hexes ? fixed(b.hex_min) : '',
                     b.hexes ? fixed(b.hex_condition_max) : ''];
      cells.forEach(function (c, i) {
        const td = document.createElement('td');
        td.textContent = c;
        if (i >= 2) td.className = 'value';
        row.appendChild(td);
      });
      const link = document.createElement('td');
      if (b.html) {
        const a = document.createElement('a');
        a.href = b.html;
        a.textContent = b.html;
        link.appendChild(a);
      }
      row.appendChild(link);
      t.appendChild(row);
    });
  }

  summary();
  bars('elements', 'Elements per block, by kind', [
    { label: 'tets', data: done.map(function (b) { return b.tets; }), backgroundColor: kindColours.tet },
    { label: 'pyramids', data: done.map(function (b) { return b.pyramids; }), backgroundColor: kindColours.pyramid },
    { label: 'hexes', data: done.map(function (b) { return b.hexes; }), backgroundColor: kindColours.hex }], true);
  bars('quality', 'Tet collapse per block', [
    { label: 'min', data: done.map(function (b) { return b.tet_min; }), backgroundColor: '#c0504d' },
    { label: 'mean', data: done.map(function (b) { return b.tet_mean; }), backgroundColor: kindColours.tet }], false);
  bars('seconds', 'Seconds per block (the block\'s own wall time)', [
    { label: 'seconds', data: done.map(function (b) { return b.seconds; }), backgroundColor: '#7f7f7f' }], false);
  table();
})();
