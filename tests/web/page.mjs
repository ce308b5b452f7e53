// Opens one close2gl page in Debian's Chromium, headless (WebGL2 on SwiftShader), waits until
// the app's status (?test=1) says the views have been compared, takes a screenshot, and prints
// {"status", "hash", "errors"} as one JSON line for tests/web_page.rs to judge. With PICK, it
// then picks that file with the page's file input (the panel's "Open a file…") and waits until
// the status shows it as the model or the trace.
//
//   node page.mjs URL SCREENSHOT.png [TIMEOUT_MS [PICK]]
import { readFileSync } from "node:fs";
import { basename } from "node:path";
import { chromium } from "playwright-core";

// Chromium's flags, shared with tests/web_page.rs's page in virtual time.
const args = JSON.parse(readFileSync(new URL("./chromium-args.json", import.meta.url), "utf8"));

const [url, screenshot, timeout = "90000", pick] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  args,
});
const errors = [];
try {
  const page = await browser.newPage({ viewport: { width: 1366, height: 768 } });
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => m.type() === "error" && errors.push(m.text()));
  await page.goto(url);
  await page.waitForFunction(
    () => {
      if (document.getElementById("error")?.textContent) return true;
      const text = document.getElementById("status")?.textContent;
      return text && JSON.parse(text).coverage_agreement !== null;
    },
    null,
    { timeout: Number(timeout), polling: 100 },
  );
  if (pick) {
    await page.setInputFiles("#close2gl-file", pick);
    await page.waitForFunction(
      (name) => {
        const status = JSON.parse(document.getElementById("status").textContent);
        return status.model === name || status.trace?.file === name;
      },
      basename(pick),
      { timeout: Number(timeout), polling: 100 },
    );
  }
  // The link follows the view within its throttle (250 ms).
  await page.waitForTimeout(600);
  await page.screenshot({ path: screenshot });
  const text = await page.textContent("#status");
  const pageError = await page.textContent("#error");
  if (pageError) errors.push(pageError);
  const hash = await page.evaluate(() => location.hash);
  console.log(JSON.stringify({ status: text ? JSON.parse(text) : null, hash, errors }));
} catch (e) {
  console.log(JSON.stringify({ status: null, hash: null, errors: [...errors, String(e)] }));
} finally {
  await browser.close();
}
