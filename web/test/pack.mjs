// The npm package as a user gets it: `npm pack` in web/npm, the tarball installed into a fresh
// temporary folder (offline: the package has no dependencies), and web/test/checks.mjs run
// there against the installed copy, then docs/web.md's example, whose output must be the one
// the page shows. Run web/build.sh first. docs/web.md, "Tests".
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const pkg = join(here, '..', 'npm');
const scratch = mkdtempSync(join(tmpdir(), 'shadow-aliasing-npm-'));
const run = (cmd, args, cwd) => execFileSync(cmd, args, { cwd, stdio: ['ignore', 'pipe', 'inherit'] }).toString();
try {
  run('npm', ['pack', '--silent', '--pack-destination', scratch], pkg);
  const tarball = readdirSync(scratch).find((f) => f.endsWith('.tgz'));
  if (!tarball) throw new Error('npm pack wrote no tarball');
  const app = join(scratch, 'app');
  run('mkdir', ['-p', app], scratch);
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
  run('npm', ['install', '--offline', '--no-audit', '--no-fund', '--silent', join(scratch, tarball)], app);
  const listed = run('tar', ['-tzf', join(scratch, tarball)], scratch).split('\n').filter(Boolean).sort();
  console.log(`packed ${tarball}: ${listed.join(', ')}`);
  copyFileSync(join(here, 'checks.mjs'), join(app, 'checks.mjs'));
  execFileSync('node', ['checks.mjs'], { cwd: app, stdio: 'inherit' });
  // docs/web.md's example: the js block after its marker, and the text block after it.
  const page = readFileSync(join(here, '..', '..', 'docs', 'web.md'), 'utf8');
  const after = page.split('<!-- example: run by web/test/pack.mjs -->')[1];
  if (!after) throw new Error('docs/web.md has no example marker');
  const example = after.split('```js\n')[1].split('```')[0];
  const shown = after.split('```text\n')[1].split('```')[0];
  writeFileSync(join(app, 'example.mjs'), example);
  const printed = run('node', ['example.mjs'], app);
  if (printed !== shown) {
    throw new Error(`docs/web.md's example printed:\n${printed}\nbut the page shows:\n${shown}`);
  }
  console.log("ok docs/web.md's example prints what the page shows");
} finally {
  rmSync(scratch, { recursive: true, force: true });
}
