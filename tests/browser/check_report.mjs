// SPDX-License-Identifier: Apache-2.0
// Renders a vrreg report in headless Chromium (Debian's, driven by playwright-core from web/) and
// checks it as a reader would see it: every chart drawn, with a title, a caption and axis titles;
// no console error, no page error, no request leaving the machine. Keeps a full-page screenshot.
//
//   node tests/browser/check_report.mjs REPORT.html SCREENSHOT.png [EXPECTED_CHARTS]
//
// Prints one JSON line {ok, charts, problems}; exits 0 when ok, 1 on a problem, 2 on a set-up
// error (no Chromium, no playwright-core). Chromium: $VRREG_CHROMIUM or /usr/bin/chromium.
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const [reportArg, screenshotArg, expectedArg] = process.argv.slice(2);
if (!reportArg || !screenshotArg) {
  console.error('usage: node check_report.mjs REPORT.html SCREENSHOT.png [EXPECTED_CHARTS]');
  process.exit(2);
}
const chromiumPath = process.env.VRREG_CHROMIUM || '/usr/bin/chromium';
if (!existsSync(chromiumPath)) {
  console.error(`Chromium is missing at ${chromiumPath}: run scripts/install-deps.sh ` +
                '(apt-get install chromium), or set VRREG_CHROMIUM');
  process.exit(2);
}
const playwrightPath = resolve(here, '../../web/node_modules/playwright-core/index.mjs');
if (!existsSync(playwrightPath)) {
  console.error(`playwright-core is missing at ${playwrightPath}: run scripts/install-deps.sh ` +
                '(npm ci in web/)');
  process.exit(2);
}
const { chromium } = await import(pathToFileURL(playwrightPath).href);

const problems = [];
const profile = mkdtempSync(join(tmpdir(), 'vrreg-chromium-'));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: chromiumPath,
  headless: true,
  viewport: { width: 1400, height: 900 },
  args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--disable-quic',
         '--no-first-run', '--disable-background-networking', '--disable-component-update',
         '--disable-sync'],
});
let charts = 0;
try {
  const page = context.pages()[0] || await context.newPage();
  // Nothing may leave the machine: only the file itself and in-page data/blob URLs load.
  await page.route('**/*', (route) => {
    const url = route.request().url();
    if (/^(file|data|blob):/.test(url)) return route.continue();
    problems.push(`request left the page: ${url}`);
    return route.abort();
  });
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(pathToFileURL(resolve(reportArg)).href, { waitUntil: 'load', timeout: 60000 });
  await page.waitForSelector('body[data-report-ready="1"]', { timeout: 60000 });
  const state = await page.evaluate(() => {
    const body = document.body;
    const figures = [...document.querySelectorAll('figure.chart')].map((fig) => {
      const plot = fig.querySelector('.plot');
      const layout = (plot && plot.layout) || {};
      const scene = layout.scene;
      const title = (axis) => (axis && axis.title && axis.title.text) || '';
      const axes = scene ? [title(scene.xaxis), title(scene.yaxis), title(scene.zaxis)]
                         : [...fig.querySelectorAll('.xtitle, .ytitle')].map((t) => t.textContent);
      return {
        id: fig.id,
        title: (fig.querySelector('h3') || {}).textContent || '',
        caption: (fig.querySelector('figcaption') || {}).textContent || '',
        rendered: !!plot && plot.getAttribute('data-rendered') === '1' &&
                  plot.classList.contains('js-plotly-plot'),
        drawn: scene ? !!plot.querySelector('canvas') : plot.querySelectorAll('.trace').length > 0,
        axes,
        scene: !!scene,
      };
    });
    return {
      expected: Number(body.getAttribute('data-charts-expected')),
      rendered: Number(body.getAttribute('data-charts-rendered')),
      errors: body.getAttribute('data-report-errors') || '',
      webglMissing: document.body.innerText.includes('WebGL is not supported'),
      figures,
    };
  });
  charts = state.rendered;
  if (state.errors) problems.push(`report errors: ${state.errors}`);
  if (state.webglMissing) problems.push('a 3D chart could not get WebGL');
  if (state.expected !== state.figures.length || state.rendered !== state.figures.length) {
    problems.push(`charts: ${state.figures.length} on the page, ${state.expected} expected, ` +
                  `${state.rendered} rendered`);
  }
  if (expectedArg !== undefined && Number(expectedArg) !== state.figures.length) {
    problems.push(`charts: ${state.figures.length} on the page, the test expected ${expectedArg}`);
  }
  for (const f of state.figures) {
    if (!f.rendered || !f.drawn) problems.push(`${f.id} (${f.title}): not drawn`);
    if (!f.title.trim() || !f.caption.trim()) problems.push(`${f.id}: no title or caption`);
    const need = f.scene ? 3 : 2;
    if (f.axes.length < need || f.axes.some((a) => !a.trim())) {
      problems.push(`${f.id} (${f.title}): axis titles missing (${JSON.stringify(f.axes)})`);
    }
  }
  await page.screenshot({ path: screenshotArg, fullPage: true });
} catch (e) {
  problems.push(`failed: ${e.message.split('\n')[0]}`);
} finally {
  await context.close();
  rmSync(profile, { recursive: true, force: true });
}
console.log(JSON.stringify({ ok: problems.length === 0, charts, problems }));
process.exit(problems.length === 0 ? 0 : 1);
