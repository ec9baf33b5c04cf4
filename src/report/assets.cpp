// SPDX-License-Identifier: Apache-2.0
#include "assets.hpp"

namespace vrreg::report::detail {

const char* const kReportCss = R"css(
:root { --ink: #1d2330; --muted: #5d6575; --line: #d9dde5; --bg: #f6f7f9; --accent: #1f5fa8; }
* { box-sizing: border-box; }
body { margin: 0; background: var(--bg); color: var(--ink);
  font: 15px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif; }
header.top { background: #1d2330; color: #fff; padding: 22px 32px 18px; }
header.top h1 { margin: 0 0 4px; font-size: 24px; font-weight: 600; }
header.top p { margin: 0; color: #c9cfdb; }
main { max-width: 1280px; margin: 0 auto; padding: 18px 32px 40px; }
nav.toc { margin: 0 0 18px; font-size: 14px; }
nav.toc a { color: var(--accent); text-decoration: none; margin-right: 16px; white-space: nowrap; }
.verdict { background: #fff; border: 1px solid var(--line); border-radius: 8px; padding: 14px 18px;
  margin: 0 0 22px; }
.verdict h2 { margin: 0 0 8px; font-size: 18px; }
.verdict ul { margin: 0; padding: 0; list-style: none; }
.verdict li { padding: 4px 0 4px 14px; border-left: 4px solid #9aa3b2; margin: 6px 0; }
.verdict li.good { border-color: #2e8b57; }
.verdict li.warn { border-color: #d9961a; }
.verdict li.bad { border-color: #c23b3b; }
section.part { margin: 0 0 26px; }
section.part > h2 { font-size: 20px; margin: 26px 0 8px; padding-bottom: 4px;
  border-bottom: 2px solid var(--line); }
section.part > p { margin: 6px 0; max-width: 980px; }
.grid { display: grid; grid-template-columns: repeat(auto-fit, minmax(520px, 1fr)); gap: 16px; }
figure.chart { margin: 0; background: #fff; border: 1px solid var(--line); border-radius: 8px;
  padding: 10px 12px 8px; break-inside: avoid; }
figure.chart.wide { grid-column: 1 / -1; }
figure.chart h3 { margin: 0 0 2px; font-size: 15px; font-weight: 600; }
figure.chart .plot { width: 100%; height: 400px; }
figure.chart.wide .plot { height: 430px; }
figure.chart.scene .plot { height: 600px; }
figure.chart figcaption { color: var(--muted); font-size: 13.5px; margin-top: 4px; }
.table-wrap { background: #fff; border: 1px solid var(--line); border-radius: 8px;
  padding: 10px 12px; margin: 10px 0 16px; overflow-x: auto; }
.table-wrap h3 { margin: 0 0 6px; font-size: 15px; }
table { border-collapse: collapse; font-variant-numeric: tabular-nums; font-size: 14px; }
th, td { padding: 4px 12px; text-align: right; border-bottom: 1px solid #eceef2; white-space: nowrap; }
th:first-child, td:first-child { text-align: left; }
th { background: #f0f2f6; font-weight: 600; }
tr.muted td, td.muted, th.muted { color: #8a91a0; font-style: italic; }
th.muted { font-weight: 500; }
tr.group-start td { border-top: 2px solid #c9ced8; }
.table-wrap p.caption { color: var(--muted); font-size: 13.5px; margin: 6px 0 0; }
footer { color: var(--muted); font-size: 13px; border-top: 1px solid var(--line); margin-top: 30px;
  padding-top: 10px; }
footer p { margin: 2px 0; }
@media print { body { background: #fff; } header.top { color: #000; background: #fff; }
  .grid { display: block; } figure.chart { margin: 0 0 12px; } }
)css";

const char* const kReportScript = R"js(
(function () {
  'use strict';
  var body = document.body;
  var errors = [];
  function fail(message) {
    errors.push(message);
    body.setAttribute('data-report-errors', errors.join(' | '));
    console.error('vrreg report: ' + message);
  }
  var specs = JSON.parse(document.getElementById('vrreg-figures').textContent);
  var base = {
    font: { family: 'system-ui, -apple-system, "Segoe UI", Roboto, Arial, sans-serif', size: 13,
            color: '#1d2330' },
    margin: { l: 70, r: 20, t: 30, b: 60 },
    paper_bgcolor: '#ffffff', plot_bgcolor: '#ffffff',
    legend: { orientation: 'h', x: 0, y: 1.12 },
    hoverlabel: { namelength: -1 }
  };
  var config = { responsive: true, displaylogo: false,
                 toImageButtonOptions: { format: 'png', scale: 2 } };
  var drawn = 0;
  var pending = specs.map(function (spec) {
    var el = document.getElementById(spec.id);
    if (!el) { fail('no element for ' + spec.id); return Promise.resolve(); }
    var layout = Object.assign({}, base, spec.layout);
    return Plotly.newPlot(el, spec.data, layout, config).then(function () {
      el.setAttribute('data-rendered', '1');
      drawn += 1;
    }, function (err) { fail(spec.id + ': ' + err); });
  });
  Promise.all(pending).then(function () {
    body.setAttribute('data-charts-rendered', String(drawn));
    body.setAttribute('data-report-ready', '1');
  });
})();
)js";

}  // namespace vrreg::report::detail
