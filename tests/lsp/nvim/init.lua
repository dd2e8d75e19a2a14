-- Neovim (Debian's 0.7) as a programmer has it: the filetype for programmes and ncsight's server
-- through the built-in client (docs/editors.md, the 0.7 setup), then, for the test, the
-- diagnostics written to $NCSIGHT_NVIM_OUT once the server has published them.
vim.api.nvim_create_autocmd({ 'BufRead', 'BufNewFile' }, {
  pattern = { '*.nc', '*.NC', '*.cnc', '*.tap' },
  callback = function() vim.bo.filetype = 'gcode' end,
})
local ncsight
vim.api.nvim_create_autocmd('FileType', {
  pattern = 'gcode',
  callback = function(args)
    if not (ncsight and vim.lsp.get_client_by_id(ncsight)) then
      ncsight = vim.lsp.start_client({
        name = 'ncsight',
        cmd = { os.getenv('NCSIGHT_BIN') or 'ncsight', 'lsp' },
        root_dir = vim.fn.getcwd(),
        init_options = { machine = 'gsk980tdi' },
      })
    end
    if ncsight then vim.lsp.buf_attach_client(args.buf, ncsight) end
  end,
})

-- The test: wait (at most 20 s) for the server's diagnostics, write them one a line as
-- "LINE CODE SEVERITY MESSAGE'S FIRST LINE", and quit.
function NcsightReport()
  local out = assert(io.open(os.getenv('NCSIGHT_NVIM_OUT'), 'w'))
  local ok = vim.wait(20000, function() return #vim.diagnostic.get(0) > 0 end, 50)
  if not ok then out:write('no diagnostics\n') end
  for _, d in ipairs(vim.diagnostic.get(0)) do
    out:write(string.format('%d %s %d %s\n', d.lnum + 1, tostring(d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code)), d.severity, (d.message:gsub('\n.*', ''))))
  end
  out:close()
  vim.cmd('qall!')
end
