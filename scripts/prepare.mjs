// npm's `prepare` hook: builds dist/ after `npm install` / `npm ci` in a clone and for installs from
// git, so that `fulcrum` resolves however it was installed. `npm pack` and `npm publish` run both
// `prepack` and `prepare`; prepack builds for those, so this skips them instead of building twice.
import { execSync } from 'node:child_process';

const command = process.env.npm_command;
if (command !== 'pack' && command !== 'publish') execSync('npm run build', { stdio: 'inherit' });
