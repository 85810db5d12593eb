-- MIRoN language server in Neovim 0.10+ (docs/lsp.md). `miron` must be on PATH, or write the
-- launcher's absolute path instead of 'miron'.
vim.filetype.add({
  extension = {
    bt = 'bt',
    roqme = 'roqme',
    miron = 'miron',
    -- BehaviorTree.CPP trees are .xml files whose root is <root> with <BehaviorTree> inside.
    xml = function(_, bufnr)
      local head = table.concat(vim.api.nvim_buf_get_lines(bufnr, 0, 50, false), '\n')
      if head:find('<root[%s>]') and head:find('<BehaviorTree[%s>/]') then
        return 'bt'
      end
      return 'xml'
    end,
  },
})

vim.api.nvim_create_autocmd('FileType', {
  pattern = { 'bt', 'roqme', 'miron' },
  callback = function(args)
    if args.match == 'bt' then
      vim.bo[args.buf].syntax = 'xml'
    end
    -- The buffer's absolute path: a relative file name (`nvim model.miron`) has no folder of its own.
    local file = vim.api.nvim_buf_get_name(args.buf)
    vim.lsp.start({
      name = 'miron',
      cmd = { 'miron', 'lsp' },
      root_dir = vim.fs.root(args.buf, { '.git' }) or vim.fs.dirname(file),
    })
  end,
})

-- :MironGenerate writes the current model's artefacts into generated/ next to it.
vim.api.nvim_create_user_command('MironGenerate', function()
  local params = { command = 'miron.generate', arguments = { vim.uri_from_bufnr(0) } }
  vim.lsp.buf_request(0, 'workspace/executeCommand', params, function(err, result)
    local message = err and err.message or (result and result.message) or 'no answer'
    vim.notify(message, (err or not (result and result.ok)) and vim.log.levels.ERROR or vim.log.levels.INFO)
  end)
end, {})
