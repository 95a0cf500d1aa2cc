import { Common } from './common';

/** A matter.js plugin: a name, a version, and `install(base)`, which patches the modules of base. */
export interface MatterPlugin {
  name: string;
  version?: string;
  for?: string;
  uses?: (MatterPlugin | string)[];
  install(base: unknown): void;
  [key: string]: unknown;
}

/** matter.js's `Plugin`: a registry of plugins and `use` to install them once. A plain, mutable module object. */
export const Plugin = {
  _registry: {} as Record<string, MatterPlugin>,

  /** Keeps `plugin` by its name (a later version replaces an earlier one); returns it. */
  register(plugin: MatterPlugin): MatterPlugin {
    const known = Plugin._registry[plugin.name];
    if (!known || (plugin.version ?? '0') >= (known.version ?? '0')) Plugin._registry[plugin.name] = plugin;
    return plugin;
  },

  /** The plugin registered under `name` (a 'name@version' string's name), or the plugin itself. */
  resolve(plugin: MatterPlugin | string): MatterPlugin | undefined {
    return typeof plugin === 'string' ? Plugin._registry[plugin.split('@')[0]] : plugin;
  },

  isPlugin(value: unknown): value is MatterPlugin {
    return (
      typeof value === 'object' &&
      value !== null &&
      typeof (value as MatterPlugin).name === 'string' &&
      typeof (value as MatterPlugin).install === 'function'
    );
  },

  /** Whether `module` has had the plugin named `name` installed. */
  isUsed(module: { used?: string[] }, name: string): boolean {
    return (module.used ?? []).includes(name);
  },

  /** Installs `plugins` (and the plugins they use first) on `module`, each once. */
  use(module: { used?: string[] }, plugins: (MatterPlugin | string)[]): void {
    module.used ??= [];
    for (const entry of plugins) {
      const plugin = Plugin.resolve(entry);
      if (!plugin) {
        Common.warn('Plugin.use:', String(entry), 'is not registered, skipped');
        continue;
      }
      if (Plugin.isUsed(module, plugin.name)) continue;
      if (plugin.uses) Plugin.use(module, plugin.uses);
      plugin.install(module);
      module.used.push(plugin.name);
    }
  },
};
