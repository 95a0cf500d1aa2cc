/**
 * The `<script>` build (dist/fulcrum.global.js): the global `Fulcrum` holds the engine's exports, and
 * `Fulcrum.render` those of `fulcrum/render`.
 */
export * from './index';
export * as render from './render/index';
