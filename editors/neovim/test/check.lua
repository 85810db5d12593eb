-- A user's session in Neovim with the documented configuration (editors/neovim/init.lua, loaded
-- with -u), run headless from a copy of the intralogistics example as the working directory.
-- Each check waits on a condition, never a fixed time; the results go as JSON to the file named
-- by $MIRON_NVIM_RESULTS (read by org.miron.cli's NeovimLspTest), then Neovim quits.
local TIMEOUT = 90000
local results = {}

local function finish()
  local file = assert(io.open(assert(vim.env.MIRON_NVIM_RESULTS), 'w'))
  file:write(vim.json.encode({ version = tostring(vim.version()), checks = results }))
  file:close()
  vim.cmd('qa!')
end

local function check(name, body)
  local ok, err = pcall(body)
  table.insert(results, { name = name, ok = ok, detail = ok and '' or tostring(err) })
  return ok
end

local function wait(what, condition)
  if not vim.wait(TIMEOUT, condition, 20) then
    error('timed out waiting for ' .. what, 2)
  end
end

-- The LSP position just after the first occurrence of text (ASCII files: bytes = UTF-16 units).
local function after(buf, text)
  for i, line in ipairs(vim.api.nvim_buf_get_lines(buf, 0, -1, false)) do
    local _, last = line:find(text, 1, true)
    if last then
      return { line = i - 1, character = last }
    end
  end
  error('not in the buffer: ' .. text, 2)
end

local function request(buf, method, params)
  local responses, err = vim.lsp.buf_request_sync(buf, method, params, TIMEOUT)
  if not responses then
    error(method .. ': ' .. tostring(err), 2)
  end
  for _, response in pairs(responses) do
    if response.error then
      error(method .. ': ' .. vim.inspect(response.error), 2)
    end
    return response.result
  end
end

local function errors(buf)
  return vim.diagnostic.get(buf, { severity = vim.diagnostic.severity.ERROR })
end

local function text(buf)
  return table.concat(vim.api.nvim_buf_get_lines(buf, 0, -1, false), '\n')
end

-- As a user types `nvim intralogistics.miron` in the model's folder: a relative file name.
vim.cmd.edit('intralogistics.miron')
local buf = vim.api.nvim_get_current_buf()
local doc = { uri = vim.uri_from_bufnr(buf) }
local client

if not check('attach', function()
  wait('the miron client', function()
    client = vim.lsp.get_clients({ bufnr = buf, name = 'miron' })[1]
    return client ~= nil and client.server_capabilities ~= nil
  end)
  assert(client.config.root_dir:sub(1, 1) == '/', 'root_dir is not absolute: ' .. client.config.root_dir)
end) then
  return finish()
end

check('diagnostics', function()
  local at = after(buf, 'affects roqme.safety')
  vim.api.nvim_buf_set_text(buf, at.line, at.character, at.line, at.character, { 'y' })
  wait('an error on roqme.safetyy', function()
    for _, d in ipairs(errors(buf)) do
      if d.message:find('safetyy', 1, true) then
        return true
      end
    end
  end)
end)

check('code action', function()
  local at = after(buf, 'affects roqme.safet')
  local diagnostics = {}
  for _, d in ipairs(errors(buf)) do
    table.insert(diagnostics, d.user_data.lsp)
  end
  local actions = request(buf, 'textDocument/codeAction',
    { textDocument = doc, range = { start = at, ['end'] = at }, context = { diagnostics = diagnostics } }) or {}
  local titles, fix = {}, nil
  for _, action in ipairs(actions) do
    table.insert(titles, action.title)
    if action.edit and action.title:find('safety', 1, true) and not action.title:find('safetyy', 1, true) then
      fix = action
    end
  end
  assert(fix, 'no quick fix to safety among: ' .. table.concat(titles, ' | '))
  vim.lsp.util.apply_workspace_edit(fix.edit, client.offset_encoding)
  wait('no more errors', function()
    return #errors(buf) == 0
  end)
end)

check('completion', function()
  local result = request(buf, 'textDocument/completion', { textDocument = doc, position = after(buf, 'dock : main.') })
  local labels = {}
  for _, item in ipairs(result.items or result) do
    labels[item.label] = true
  end
  assert(labels['main.Charge'] and labels['main.PickDeliverCharge'], 'labels: ' .. vim.inspect(vim.tbl_keys(labels)))
end)

check('hover', function()
  local result = request(buf, 'textDocument/hover', { textDocument = doc, position = after(buf, 'affects roqme.safe') })
  local value = result and result.contents and (result.contents.value or vim.inspect(result.contents)) or ''
  assert(value:find('Safety of the navigation', 1, true), 'hover: ' .. value)
end)

check('definition', function()
  local result = request(buf, 'textDocument/definition', { textDocument = doc, position = after(buf, 'dock : main.Cha') })
  local location = result and (result.uri and result or result[1])
  assert(location and (location.uri or location.targetUri):find('intralogistics%.bt$'), vim.inspect(result))
end)

check('rename', function()
  local at = after(buf, '@varpoint maxVelo')
  vim.api.nvim_win_set_cursor(0, { at.line + 1, at.character })
  vim.lsp.buf.rename('maxSpeed')
  wait('the varpoint renamed', function()
    return text(buf):find('@varpoint maxSpeed', 1, true) ~= nil
  end)
end)

check('formatting', function()
  -- The indentation the user set (Neovim sends it as the formatting options): two spaces.
  vim.bo[buf].expandtab = true
  vim.bo[buf].shiftwidth = 2
  vim.bo[buf].tabstop = 2
  local at = after(buf, 'affects roqme.safety++')
  local line = vim.api.nvim_buf_get_lines(buf, at.line, at.line + 1, false)[1]
  vim.api.nvim_buf_set_lines(buf, at.line, at.line + 1, false, { '10     affects   roqme.safety++,' })
  vim.lsp.buf.format({ bufnr = buf, async = false, timeout_ms = TIMEOUT })
  local formatted = vim.api.nvim_buf_get_lines(buf, at.line, at.line + 1, false)[1]
  assert(formatted == line, 'formatted: "' .. tostring(formatted) .. '", expected "' .. line .. '"')
end)

check('miron.generate', function()
  vim.cmd('MironGenerate')
  wait('generated/intralogistics.mzn', function()
    return vim.uv.fs_stat('generated/intralogistics.mzn') ~= nil and vim.uv.fs_stat('generated/intralogistics.io.json') ~= nil
  end)
end)

-- The .roqme is not open: only the file system tells the server (Neovim on Linux sends no
-- workspace/didChangeWatchedFiles unless it can watch; the server then watches itself).
check('change on disk', function()
  assert(os.rename('intralogistics.roqme', 'moved.roqme'))
  wait('errors after the .roqme left', function()
    return #errors(buf) > 0
  end)
  assert(os.rename('moved.roqme', 'intralogistics.roqme'))
  wait('no errors once it is back', function()
    return #errors(buf) == 0
  end)
end)

check('behaviour tree xml', function()
  vim.cmd.edit('tree.xml')
  local tree = vim.api.nvim_get_current_buf()
  assert(vim.bo[tree].filetype == 'bt', 'tree.xml filetype: ' .. vim.bo[tree].filetype)
  wait('the miron client on tree.xml', function()
    return vim.lsp.get_clients({ bufnr = tree, name = 'miron' })[1] ~= nil
  end)
  wait('the error of tree.xml', function()
    return #errors(tree) > 0
  end)
  vim.cmd.edit('pom.xml')
  local pom = vim.api.nvim_get_current_buf()
  assert(vim.bo[pom].filetype == 'xml', 'pom.xml filetype: ' .. vim.bo[pom].filetype)
  assert(#vim.lsp.get_clients({ bufnr = pom, name = 'miron' }) == 0, 'the server attached to pom.xml')
end)

finish()
